// A structure's mass, centre of mass and moment of inertia from its mesh and density
// (docs/theory.md eq. 17.6), integrated cell by cell with each cell's Gauss rule (exact for the
// quadratic integrands of straight-sided cells).
#pragma once

#include "geompm/core/types.hpp"
#include "geompm/structures/structure_mesh.hpp"

namespace geompm {

struct MassProperties {
  /// Per unit thickness (plane strain), per radian (axisymmetry) or of the whole body (3D).
  double mass = 0.0;
  /// The centre of mass; in axisymmetry on the axis (x = 0).
  Vec3 centroid = Vec3::Zero();
  /// About the centre of mass: J = integral of rho (|r|^2 I - r r^T), r = x - centroid (in 2D,
  /// J(2, 2) is the polar moment; in axisymmetry only J(1, 1), about the axis, is kept).
  Mat3 inertia = Mat3::Zero();
};

MassProperties mass_properties(const StructureMesh& mesh, double density);

/// J about the point `reference` of a body of mass m whose J about its centre of mass is given
/// (parallel axes): J + m (|s|^2 I - s s^T), s = centroid - reference.
Mat3 inertia_about(const MassProperties& body, const Vec3& reference);

}  // namespace geompm
