// Small tensor and index types shared by every room of geompm.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
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

/// The Euclidean norm and the largest of the first `dim` components of `v`, as loops: Eigen's
/// dynamic-size head() of a fixed-size vector makes GCC 12 warn about array bounds it keeps.
inline double head_norm(const Vec3& v, int dim) {
  double sum = 0.0;
  for (int i = 0; i < dim; ++i) sum += v(i) * v(i);
  return std::sqrt(sum);
}
inline double head_max(const Vec3& v, int dim) {
  double largest = v(0);
  for (int i = 1; i < dim; ++i) largest = std::max(largest, v(i));
  return largest;
}

const char* to_string(Kinematics k);

}  // namespace geompm
