#include "geompm/physics/body_loads.hpp"

namespace geompm {

BodyLoads::BodyLoads(const GridSystem& grid, const MaterialPoints& points, const DofMap& dofs,
                     const Vec3& gravity, const std::vector<PointSetForce>& forces) {
  f_ext_ = Vector::Zero(dofs.size());
  const int u = dofs.find("displacement");
  const Index n_points = points.size();
  // Share of each point set's force per point: by mass, or by volume for a massless set.
  std::vector<double> set_mass(forces.size(), 0.0), set_volume(forces.size(), 0.0);
  for (std::size_t k = 0; k < forces.size(); ++k)
    for (Index p = 0; p < n_points; ++p)
      if (points.sets[p] >> forces[k].set & 1u) {
        set_mass[k] += points.mass[p];
        set_volume[k] += points.volume[p];
      }
  if (grid.communicator().distributed()) {  // the sets' points on every process
    grid.communicator().sum(set_mass);
    grid.communicator().sum(set_volume);
  }
  for (Index p = 0; p < n_points; ++p) {
    Vec3 force = points.mass[p] * gravity;
    for (std::size_t k = 0; k < forces.size(); ++k)
      if (points.sets[p] >> forces[k].set & 1u)
        force += forces[k].force * (set_mass[k] > 0 ? points.mass[p] / set_mass[k]
                                                    : points.volume[p] / set_volume[k]);
    grid.for_each_weight(points, p, [&](Index node, double N) {
      for (int i = 0; i < grid.dim(); ++i) f_ext_(dofs.dof(u, node, i)) += N * force(i);
    });
  }
}

bool BodyLoads::add(const Vector& /*du*/, SystemForces& forces, SparseMatrix* /*tangent*/) {
  forces.external += f_ext_;
  return true;
}

}  // namespace geompm
