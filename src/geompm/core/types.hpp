// Small tensor and index types shared by every room of geompm.
#pragma once

#include <Eigen/Core>
#include <cstdint>

namespace geompm {

using Index = std::int32_t;
using Vec3 = Eigen::Vector3d;  // positions and vectors; z = 0 in 2D
using Mat3 = Eigen::Matrix3d;  // stresses, deformation gradients (3x3 also in 2D)

/// How a 2D or 3D model is read. Plane strain and axisymmetric share the 2D code path: the
/// out-of-plane (hoop) component of the deformation gradient is 1 in plane strain and r/R in
/// axisymmetry (x is the radius); volumes and integrals are per radian in axisymmetry.
enum class Kinematics { PlaneStrain, Axisymmetric, ThreeD };

inline int spatial_dimension(Kinematics k) { return k == Kinematics::ThreeD ? 3 : 2; }

const char* to_string(Kinematics k);

}  // namespace geompm
