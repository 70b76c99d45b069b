// The equations of one step (docs/architecture.md): the step's unknowns (a DofMap over the grid's
// active nodes), the contributions whose sum is the residual R = f_ext - f_int - M a (seed eq. 6)
// and its tangent, and the tangent's pattern, built once from every contribution's couplings and
// filled at each Newton evaluation.
#pragma once

#include <memory>
#include <vector>

#include "geompm/dofs/dof_map.hpp"
#include "geompm/physics/contribution.hpp"
#include "geompm/physics/grid_system.hpp"

namespace geompm {

class StepSystem {
 public:
  /// The unknowns of a step on `grid` (after its initialise()): the displacement increment (dim
  /// per active node) and, if some material is mixed, the scaled pressure change (one per node,
  /// docs/theory.md eq. 11.6).
  explicit StepSystem(const GridSystem& grid);

  DofMap& dofs() { return dofs_; }
  const DofMap& dofs() const { return dofs_; }
  /// Adds a term; the step evaluates them in the order they were added.
  template <class T>
  T& add(std::unique_ptr<T> contribution) {
    T& added = *contribution;
    contributions_.push_back(std::move(contribution));
    return added;
  }
  const std::vector<std::unique_ptr<Contribution>>& contributions() const { return contributions_; }
  /// The first contribution of type T, or null.
  template <class T>
  T* find() const {
    for (const auto& c : contributions_)
      if (auto* found = dynamic_cast<T*>(c.get())) return found;
    return nullptr;
  }

  /// Once the constraints are set: numbers the free unknowns and builds the tangent's pattern
  /// from every contribution's couplings.
  void build_pattern();
  /// The three force sums at the step's unknowns du (every unknown) and, if `with_tangent`, the
  /// tangent at the free unknowns in tangent(). False if a contribution vetoes du. In a
  /// distributed run the sums are the whole grid's (summed over the processes) and the tangent
  /// is this process's share.
  bool evaluate(const Vector& du, SystemForces& forces, bool with_tangent);
  /// The processes of the run (its grid's).
  const Communicator& communicator() const { return communicator_; }
  /// The tangent's storage (its pattern is the step's).
  SparseMatrix& tangent() { return tangent_; }

  void report(const Vector& du, Reactions& reactions);
  void commit();

 private:
  DofMap dofs_;
  const Communicator& communicator_;
  std::vector<std::unique_ptr<Contribution>> contributions_;
  SparseMatrix tangent_;
};

}  // namespace geompm
