#include "geompm/structures/mass_properties.hpp"

#include <Eigen/LU>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/structures/structure_quadrature.hpp"

namespace geompm {

namespace {

// Sums f(x, w) over every Gauss point x of the mesh with its weight w.
template <class F>
void integrate(const StructureMesh& structure, F&& f) {
  for_each_gauss_point(structure, [&](Index, int, const Vec3& x, double w) { f(x, w); });
}

}  // namespace

MassProperties mass_properties(const StructureMesh& structure, double density) {
  MassProperties p;
  double volume = 0.0;
  Vec3 first = Vec3::Zero();
  integrate(structure, [&](const Vec3& x, double w) {
    volume += w;
    first += w * x;
  });
  p.mass = density * volume;
  p.centroid = first / volume;
  const bool axisymmetric = structure.kinematics() == Kinematics::Axisymmetric;
  if (axisymmetric) p.centroid.x() = 0.0;  // the body of revolution's centre is on its axis
  integrate(structure, [&](const Vec3& x, double w) {
    if (axisymmetric) {
      p.inertia(1, 1) += density * w * x.x() * x.x();
      return;
    }
    const Vec3 r = x - p.centroid;
    p.inertia += density * w * (r.squaredNorm() * Mat3::Identity() - r * r.transpose());
  });
  return p;
}

Mat3 inertia_about(const MassProperties& body, const Vec3& reference) {
  const Vec3 s = body.centroid - reference;
  return body.inertia + body.mass * (s.squaredNorm() * Mat3::Identity() - s * s.transpose());
}

}  // namespace geompm
