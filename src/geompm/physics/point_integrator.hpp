// The material points' internal force and tangent (seed eqs. 5 and 10): each point's stress
// update from the step's nodal increments through its stencil, in the displacement or the mixed
// p-u formulation (docs/theory.md §11, with the pressure stabilisation of eqs. 11.5 and 11.9-11.10)
// and with its cell's averaged volume change where asked (F-bar, §12). Cells are assembled in
// parallel, one colour at a time (no two cells of a colour share a node), each point by one
// thread, so the sums do not depend on the thread count. Points with a wide stencil (DDMP, GIMP,
// any stencil an Interpolation builds) are integrated in parallel too, in chunks of cells, and
// scattered in point order, which again does not depend on the thread count. Both loops call the
// same point kernel (physics/point_kernel.hpp); the cell loop has the cell's node count at compile
// time (fixed-size matrices), a wide stencil its size at run time. Cell terms (the empty-cell
// stiffness) and point terms (a prescribed motion's springs) are assembled
// with the points, into the same local vector and matrix (physics/local_terms.hpp).
#pragma once

#include <memory>
#include <vector>

#include "geompm/physics/contribution.hpp"
#include "geompm/physics/grid_system.hpp"
#include "geompm/physics/local_terms.hpp"
#include "geompm/physics/pressure_field.hpp"

namespace geompm {

struct PointStartState;  // physics/point_kernel.hpp
template <int NS, int Dim>
struct AveragedVolumeChange;
template <int NS, int Dim>
struct Stencil;
struct FiniteStrainState;

class PointIntegrator final : public Contribution {
 public:
  /// `pressure`: the step's pressure field when the DofMap has one (mixed p-u), else null.
  PointIntegrator(const GridSystem& grid, const MaterialPoints& points, const DofMap& dofs,
                  const PressureField* pressure);
  const char* name() const override { return "material points"; }
  bool sums_own_points() const override { return true; }
  /// The nodes of each active cell, of each wide stencil and of each averaged cell's union.
  void declare_couplings(SparsityBuilder& pattern) const override;
  /// Where each cell's entries go in the tangent.
  void attach(const SparseMatrix& pattern) override;
  bool add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) override;

  /// A constant matrix per cell, assembled first in each cell (owned).
  void add_cell_term(std::unique_ptr<CellTerm> term) { cell_terms_.push_back(std::move(term)); }
  /// A force at the points it acts on, assembled after each point's own (owned by the step's
  /// system as a contribution), in the order they were added.
  void add_point_term(PointTerm* term) { point_terms_.push_back(term); }

  /// Writes into `points` the state the internal force computes at `du` (stress, F, b_e,
  /// internal variables, volume): one more evaluation, without the tangent, instead of keeping
  /// a trial copy of every point's state through Newton (docs/performance.md: memory).
  bool commit_state(MaterialPoints& points, const Vector& du);

  /// Per point (cell-sorted order): 1 if the last evaluation returned it plastically.
  const std::vector<char>& plastic_points() const { return plastic_; }
  /// After add() returned false: the (lowest-numbered) point whose deformation was
  /// inadmissible, or -1, and whether its stress update failed (rather than its volume <= 0).
  Index inadmissible_point() const { return inadmissible_point_; }
  bool inadmissible_by_stress_update() const { return inadmissible_by_stress_update_; }

 private:
  template <class E, bool Mixed>
  bool add_cells(const Vector& du, Vector& f_int, SparseMatrix* tangent);
  /// One cell of a colour: its pressure stabilisation and its points, scattered.
  template <class E, bool Mixed>
  bool add_cell(Index ci, const Vector& du, Vector& f_int, SparseMatrix* tangent);
  /// The points [begin of cell ci, point_end) into the cell's force and stiffness.
  template <class E, bool Mixed, class Displacements, class Pressures, class Average,
            class CellForce, class CellStiffness>
  bool integrate_cell_points(Index ci, Index point_end, const Displacements& du_local,
                             const Pressures& p_local, const Average& average, bool with_tangent,
                             CellForce& f_cell, CellStiffness& K_cell) const;
  template <int Dim>
  bool add_wide_stencil_points(const Vector& du, Vector& f_int, SparseMatrix* tangent);
  template <int Dim>
  struct WideWork;
  /// A point's force and stiffness over its unknowns, before they are scattered.
  struct PointLocal {
    std::vector<Index> dofs;
    Eigen::VectorXd f;
    Eigen::MatrixXd K;
  };
  template <int Dim>
  bool integrate_wide_cell(Index ci, const Vector& du, bool with_tangent, WideWork<Dim>& work,
                           Index offset) const;
  template <int Dim>
  bool integrate_wide_point(Index p, const Vector& du, bool averaged, bool with_tangent,
                            WideWork<Dim>& work, PointLocal& local) const;
  template <class E>
  Stencil<E::nodes, E::dim> cell_stencil(Index p) const;
  template <int NS, int Dim, class StencilOf>
  bool average_volume_change(Index ci, const Eigen::Matrix<double, NS, Dim>& du,
                             StencilOf&& stencil_of, AveragedVolumeChange<NS, Dim>& average) const;
  template <class E>
  void pressure_stabilisation(Index ci, Eigen::Matrix<double, E::nodes, E::nodes>& S) const;
  PointStartState start_state(Index p) const;
  /// The point terms' forces at point p into its local force and stiffness, with its weights N
  /// and the local displacements du of its stencil.
  template <int NS, int Dim, class Force, class Stiffness>
  void add_point_terms(Index p, const Eigen::Matrix<double, NS, 1>& N,
                       const Eigen::Matrix<double, NS, Dim>& du, bool with_tangent, Force& f,
                       Stiffness& K) const;
  /// The unknown of local unknown l of a cell or stencil of `count` active nodes: the
  /// displacements node by node, then the pressures (l >= count * dim).
  template <class Nodes>
  Index local_dof(const Nodes& active, int count, int l) const {
    const int n = count * dim_;
    return l < n ? dofs_.dof(displacement_, active[l / dim_], l % dim_)
                 : dofs_.dof(pressure_field_, active[l - n]);
  }
  /// Unknowns of a cell of `nen` nodes; by default of the largest cell (the scatter's stride).
  int cell_unknowns(int nen) const { return nen * dim_ + (pressure_ ? nen : 0); }
  int cell_unknowns() const { return cell_unknowns(nen_); }
  void note_inadmissible(Index p, bool stress_update_failed = false) const;
  /// Point p's updated state at the current evaluation: written to the points only when
  /// commit_state() asks for it (`stress`: the total stress, which the mixed formulation
  /// changes; `own_volume`: the volume its own deformation gives, which differs from `volume`
  /// with a cell's volume average and stretches its domain, eq. 12.7).
  void commit(Index p, const FiniteStrainState& state, double volume, const Mat3& stress,
              double own_volume, double volume_mismatch = 0.0) const;

  const GridSystem& grid_;
  const MaterialPoints& points_;
  const DofMap& dofs_;
  const PressureField* pressure_;
  int dim_, nen_;
  int displacement_ = 0, pressure_field_ = -1;
  std::vector<std::unique_ptr<CellTerm>> cell_terms_;
  std::vector<PointTerm*> point_terms_;
  mutable std::vector<PointLocal> wide_locals_;  // per point of a chunk of wide-stencil cells
  std::vector<int> scatter_;           // cell_unknowns()^2 per active cell: value position or -1
  mutable std::vector<char> plastic_;  // per point: plastic in the last evaluation
  mutable Index inadmissible_point_ = -1;
  mutable bool inadmissible_by_stress_update_ = false;
  MaterialPoints* commit_to_ = nullptr;  // set by commit_state() only
};

}  // namespace geompm
