// Forces that act at a point and depend on its displacement alone, given by a force law: the
// penalty spring of a prescribed point motion (docs/theory.md eq. 5.1). A force F(u) with
// D = dF/du, u = sum_a N_a du_a, enters f_int as F N_a and the tangent as N_a N_b D. The point
// integrator assembles them with the points, in their cells (physics/local_terms.hpp); as a
// contribution a point force only reports and commits.
#pragma once

#include <functional>
#include <vector>

#include "geompm/physics/contribution.hpp"
#include "geompm/physics/grid_system.hpp"
#include "geompm/physics/local_terms.hpp"

namespace geompm {

/// The force at point p as it enters f_int (minus the force on the point) and its
/// stiffness d force / d u, for its displacement u over the step. Called from several
/// threads at once, for different points.
using PointForceLaw = std::function<void(Index p, const Vec3& u, Vec3& force, Mat3& stiffness)>;

class PointForces : public Contribution, public PointTerm {
 public:
  /// The law acts on the points with acts[p] != 0.
  PointForces(const char* name, const GridSystem& grid, const MaterialPoints& points,
              std::vector<char> acts, PointForceLaw law);
  const char* name() const override { return name_; }
  /// Assembled by the point integrator, with the points (PointTerm).
  bool add(const Vector&, SystemForces&, SparseMatrix*) override { return true; }

  bool acts(Index p) const override { return acts_[p] != 0; }
  void force(Index p, const Vec3& u, Vec3& force, Mat3& stiffness) override {
    law_(p, u, force, stiffness);
  }

 protected:
  const GridSystem& grid_;
  const MaterialPoints& points_;
  std::vector<char> acts_;

 private:
  const char* name_;
  PointForceLaw law_;
};

}  // namespace geompm
