// Forces that act at one place of a point's domain and depend on that place's displacement
// alone, given by a force law: the contact of a rigid footing at the top of the point's domain
// (docs/theory.md eq. 13.6), the penalty spring of a prescribed point motion at the point itself
// (eq. 5.1). A force F(u) with D = dF/du at the place x_p + offset, which moves with the step's
// deformation by u = sum_a W_a du_a (W_a = N_a + grad N_a . offset), enters f_int as F W_a and
// the tangent as W_a W_b D. The point integrator assembles them with the points, in their cells
// (physics/local_terms.hpp); as a contribution a point force only reports and commits.
#pragma once

#include <functional>
#include <vector>

#include "geompm/physics/contribution.hpp"
#include "geompm/physics/grid_system.hpp"
#include "geompm/physics/local_terms.hpp"

namespace geompm {

/// The force at point p's place as it enters f_int (minus the force on the point) and its
/// stiffness d force / d u, for the place's displacement u over the step. Called from several
/// threads at once, for different points.
using PointForceLaw = std::function<void(Index p, const Vec3& u, Vec3& force, Mat3& stiffness)>;

class PointForces : public Contribution, public PointTerm {
 public:
  /// The law acts on the points with acts[p] != 0, at x_p + offset[p] (offset may be empty: at
  /// the points).
  PointForces(const char* name, const GridSystem& grid, const MaterialPoints& points,
              const DofMap& dofs, std::vector<char> acts, std::vector<Vec3> offset,
              PointForceLaw law);
  const char* name() const override { return name_; }
  /// Assembled by the point integrator, with the points (PointTerm).
  bool add(const Vector&, SystemForces&, SparseMatrix*) override { return true; }

  bool acts(Index p) const override { return acts_[p] != 0; }
  Vec3 offset(Index p) const override { return offset_[p]; }
  void force(Index p, const Vec3& u, Vec3& force, Mat3& stiffness) override {
    law_(p, u, force, stiffness);
  }

 protected:
  /// The displacement over the step of point p's place at the step's unknowns du (the grid's
  /// place weights, in the order of its nodes).
  Vec3 place_displacement(Index p, const Vector& du) const;
  const GridSystem& grid_;
  const MaterialPoints& points_;
  const DofMap& dofs_;
  std::vector<char> acts_;
  std::vector<Vec3> offset_;

 private:
  const char* name_;
  PointForceLaw law_;
  int displacement_;
};

}  // namespace geompm
