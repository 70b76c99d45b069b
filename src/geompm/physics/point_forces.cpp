#include "geompm/physics/point_forces.hpp"

namespace geompm {

PointForces::PointForces(const char* name, const GridSystem& grid, const MaterialPoints& points,
                         const DofMap& dofs, std::vector<char> acts, std::vector<Vec3> offset,
                         PointForceLaw law)
    : grid_(grid),
      points_(points),
      dofs_(dofs),
      acts_(std::move(acts)),
      offset_(std::move(offset)),
      name_(name),
      law_(std::move(law)),
      displacement_(dofs.find("displacement")) {
  if (offset_.empty()) offset_.assign(acts_.size(), Vec3::Zero());
}

Vec3 PointForces::place_displacement(Index p, const Vector& du) const {
  PlaceWeights weights;
  grid_.place_weights(points_, p, offset_[p], weights);
  Vec3 u = Vec3::Zero();
  for (std::size_t a = 0; a < weights.nodes.size(); ++a)
    for (int i = 0; i < grid_.dim(); ++i)
      u(i) += weights.W[a] * du(dofs_.dof(displacement_, weights.nodes[a], i));
  return u;
}

}  // namespace geompm
