// Prescribed motion of points (docs/theory.md §5): point p is pulled towards its target
// displacement increment of the step (the components with bit i of its mask) by a penalty spring
// k_p (u_p - target_p) at the point (eq. 5.1). Its reaction, summed over each driven point set, is
// the force the prescribed motion exerts on the body.
#pragma once

#include <vector>

#include "geompm/physics/point_forces.hpp"

namespace geompm {

/// A driven point's spring against its own stiffness scale E V / h^2 (eq. 5.1): the motion is
/// met to about 1e-4 of the deformation without a user parameter.
inline constexpr double spring_ratio = 1e4;

struct PointTargets {
  std::vector<double> stiffness;  // per point; 0: no target
  std::vector<Vec3> target;
  std::vector<unsigned char> mask;
  std::vector<int> sets;  // the point-set bits of the driven sets (their reactions are reported)
};

class PointSprings final : public PointForces {
 public:
  PointSprings(const GridSystem& grid, const MaterialPoints& points, PointTargets targets);
  /// Per driven set: the force its springs exerted on the body at the last evaluation.
  void report(const Vector& du, Reactions& reactions) override;
  bool sums_own_points() const override { return true; }
  /// The forces the step's prescribed increments would take in the body's own stiffness,
  /// |(k_p / spring_ratio) target_p| over the driven components: the force scale of a body
  /// driven through a rigid motion, whose stresses and spring forces are all round-off.
  double driving_force_scale() const;

 private:
  void spring(Index p, const Vec3& u, Vec3& force, Mat3& stiffness);
  PointTargets targets_;
  std::vector<Vec3> reaction_;  // per point, at the last evaluation
};

}  // namespace geompm
