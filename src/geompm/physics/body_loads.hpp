// Gravity on the points' mass and forces on point sets (f_ext, seed eq. 6), mapped to the nodes
// through each point's weights once a step.
#pragma once

#include <vector>

#include "geompm/physics/contribution.hpp"
#include "geompm/physics/grid_system.hpp"

namespace geompm {

/// A force on the points of a point set (bit `set` of MaterialPoints::sets), shared in
/// proportion to the points' mass (volume if the set is massless).
struct PointSetForce {
  int set = 0;
  Vec3 force = Vec3::Zero();
};

class BodyLoads final : public Contribution {
 public:
  BodyLoads(const GridSystem& grid, const MaterialPoints& points, const DofMap& dofs,
            const Vec3& gravity, const std::vector<PointSetForce>& forces);
  const char* name() const override { return "gravity and point loads"; }
  bool sums_own_points() const override { return true; }
  bool add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) override;
  /// f_ext per unknown.
  const Vector& force() const { return f_ext_; }

 private:
  Vector f_ext_;
};

}  // namespace geompm
