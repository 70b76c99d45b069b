// The computational grid of one step (seed paper Fig. 1): built from the material points at the
// start of the step (phase 1, initialise), deformed by Newton (phase 2, Lagrangian), and read back
// into the points before it is reset (phase 3, convect).
//
// Unknowns are the nodal displacement increments of the step, numbered node-major over the
// active nodes (index = active node * dim + component). With the mixed p-u formulation
// (docs/theory.md §11) every active node also carries a pressure unknown, numbered after all
// displacements (index = active nodes * dim + active node): the pressure's change over the step
// divided by a scale s = G/h, so that it is a length like the displacements and its equation,
// multiplied by s, a force (theory eq. 11.6) - one residual norm and one correction norm serve. The
// tangent is assembled only for the free unknowns, into a pattern built once per step; assembly
// runs in parallel over cells of one colour at a time (no two cells of a colour share a node),
// which also makes the sums independent of the thread count.
#pragma once

#include <Eigen/Core>
#include <cmath>
#include <cstdint>
#include <functional>
#include <optional>
#include <vector>

#include "geompm/materials/material.hpp"
#include "geompm/mesh/mesh.hpp"
#include "geompm/mesh/mesh_topology.hpp"
#include "geompm/mesh/rectilinear_grid.hpp"
#include "geompm/physics/finite_strain.hpp"
#include "geompm/physics/node_block.hpp"
#include "geompm/points/material_points.hpp"
#include "geompm/solver/linear_solver.hpp"

namespace geompm {

struct PointStartState;  // physics/point_kernel.hpp
template <int NS, int Dim>
struct AveragedVolumeChange;
template <int NS, int Dim>
struct Stencil;

/// How points see the grid: the shape functions of their cell (standard MPM), DDMP gradients
/// (docs/theory.md §8) or GIMP weights over the point's domain (§9; rectilinear grids only).
enum class GridInterpolation { Standard, DualDomain, Gimp };

struct GridSettings {
  Kinematics kinematics = Kinematics::PlaneStrain;
  double empty_cell_modulus = 0.0;  // Young's modulus of the empty-cell stiffness (seed §3.2)
  /// Young's modulus of the springs at nodes the points barely support (docs/theory.md eq. 6.2):
  /// 0 for none; they act on nodes whose support fill is below sparse_node_fill.
  double sparse_node_modulus = 0.0;
  double sparse_node_fill = 0.05;
  /// gamma of the ghost penalty on the faces of the body's edge cells (docs/theory.md eq. 6.3),
  /// relative to the cells' own Young's modulus; 0 for none. An edge cell counts while its points
  /// fill at most ghost_penalty_fill of it.
  double ghost_penalty = 0.0;
  double ghost_penalty_fill = 0.5;
  int buffer_layers = 1;  // layers of empty cells activated around occupied cells
  GridInterpolation interpolation = GridInterpolation::Standard;
  /// Per material index: 1 if its points use the mixed p-u formulation (docs/theory.md §11). The
  /// system has pressure unknowns when any material is mixed.
  std::vector<char> mixed;
  /// Per material index: 1 if its points see the average volume change of their cell's averaged
  /// points (F-bar, docs/theory.md §12) - mixed points so that their volumes cannot drift apart,
  /// displacement points so that plastic flow keeps (or dilates) one volume per cell rather than
  /// one per point; 0: each point its own.
  std::vector<char> volume_average;
  /// Mixed points evaluate their material at the volume whose pressure is the field's
  /// (docs/theory.md §14) rather than at their kinematic volume.
  bool mixed_field_pressure = false;
  /// Mixed points tie the step's change of their material pressure to the field's (eq. 11.8), and
  /// the stabilisation acts on the step's pressure change (eq. 11.9), rather than the totals.
  bool mixed_incremental_pressure = false;
  /// The share of the exactly integrated projection added to the points' sum in the pressure
  /// stabilisation (theory eq. 11.10); 0: the points' sum alone (eq. 11.5).
  double pressure_stabilisation_floor = 0.0;
  /// Mixed p-u: start each step from the last converged nodal pressure smoothed by a local linear
  /// least-squares fit where it was well supported (theory eq. 11.11), rather than from the
  /// points' pressures (eq. 11.6).
  bool fitted_pressure_start = false;
};

/// A force on the points of a point set (bit `set` of MaterialPoints::sets), shared in
/// proportion to the points' mass (volume if the set is massless).
struct PointSetForce {
  int set = 0;
  Vec3 force = Vec3::Zero();
};

/// A force on material point p that depends on the point's displacement increment u_p =
/// sum_a N_a du_a of the step (contact with a rigid footing, docs/theory.md §13): `force` as it
/// enters f_int (minus the force on the point) and `stiffness` = d force / d u_p. Called from
/// several threads at once, for different points.
using PointForceLaw = std::function<void(Index p, const Vec3& u, Vec3& force, Mat3& stiffness)>;

class GridSystem {
 public:
  /// Throws std::invalid_argument if GIMP is asked for on a mesh that is not a rectilinear grid.
  GridSystem(const Mesh& mesh, const MeshTopology& topology,
             const std::vector<const Material*>& materials, const GridSettings& settings);

  // --- phase 1: initialise -------------------------------------------------------------
  /// Sorts the points by cell, finds active cells (occupied + buffer) and nodes, colours the
  /// cells, computes each point's shape functions and gradients, and maps mass, momentum and
  /// acceleration to the nodes (seed eq. 9).
  void initialise(MaterialPoints& points);
  /// f_ext: gravity on the points' mass and point-set forces, dof-indexed.
  Vector external_force(const MaterialPoints& points, const Vec3& gravity,
                        const std::vector<PointSetForce>& forces) const;
  /// Prescribed motion of points (docs/theory.md §5): point p is pulled towards its target
  /// displacement increment of the step (components with mask bit i) by a penalty spring of
  /// stiffness `stiffness[p]` (0: no target). Call after initialise(), before Newton.
  void set_point_targets(std::vector<double> stiffness, std::vector<Vec3> target,
                         std::vector<unsigned char> mask);
  /// The force each point's target spring exerts on the body at the last evaluation (the
  /// reaction of a prescribed motion, summed over a point set).
  const std::vector<Vec3>& point_reactions() const { return point_reaction_; }
  /// A force law on the points with acts[p] != 0, acting at a place of the point's domain: the
  /// point x_p + offset[p] carried by the deformation of the step, whose displacement is
  /// u = sum_a W_a du_a with W_a = N_a + grad N_a . offset[p] (the top of a domain that a footing
  /// touches, docs/theory.md eq. 13.6). f_int += force W_a, tangent += W_a W_b stiffness. Call
  /// after initialise() (which removes it), before Newton.
  void set_point_force_law(std::vector<char> acts, std::vector<Vec3> offset, PointForceLaw law);

  /// Marks the constrained unknowns; builds the free numbering, the tangent's pattern and the
  /// cells' scatter maps.
  void set_constraints(const std::vector<char>& constrained);

  // --- phase 2: Lagrangian --------------------------------------------------------------
  /// Internal force f_int(du) at every unknown and, if `tangent`, the tangent at the free
  /// unknowns (material + geometric, seed eq. 10, plus the empty-cell stiffness). Stores each
  /// point's trial state for convect(). False if a point's deformation is inadmissible.
  bool internal_force(const MaterialPoints& points, const Vector& du, Vector& f_int,
                      SparseMatrix* tangent);
  /// After internal_force returned false: the (lowest-numbered) point whose deformation was
  /// inadmissible, or -1 (for the failure message).
  Index inadmissible_point() const { return inadmissible_point_; }
  /// Whether that point failed in its material's stress update (a return mapping that did not
  /// converge) rather than by a volume <= 0.
  bool inadmissible_by_stress_update() const { return inadmissible_by_stress_update_; }

  /// Writes into `points` the state the internal force computes at `du` (stress, F, b_e,
  /// internal variables, volume): one more evaluation, without the tangent, instead of keeping
  /// a trial copy of every point's state through Newton (docs/performance.md: memory).
  bool commit_state(MaterialPoints& points, const Vector& du);

  // --- phase 3: convect ------------------------------------------------------------------
  /// Commits the points' state at the converged solution (commit_state) and moves them with
  /// it; the velocity and acceleration are updated from the nodal ones (FLIP increments; seed
  /// §2).
  void convect(MaterialPoints& points, const Vector& du, const Vector& velocity,
               const Vector& acceleration, double dt, bool dynamic);
  /// Forgets the last converged nodal pressure (eq. 11.11), so that a phase's first step starts
  /// from its points' pressures.
  void forget_pressure_field() { last_pressure_.clear(); }
  /// That pressure, as a checkpoint saves it (empty when there is none) and restores it.
  const std::vector<double>& last_pressure() const { return last_pressure_; }
  void restore_last_pressure(std::vector<double> pressure) { last_pressure_ = std::move(pressure); }

  // --- grid data --------------------------------------------------------------------------
  int dim() const { return dim_; }
  Index num_dofs() const {
    return static_cast<Index>(active_nodes_.size()) * (dim_ + (mixed_ ? 1 : 0));
  }
  /// True if the system has pressure unknowns (some material is mixed).
  bool mixed() const { return mixed_; }
  /// The unknown that carries the pressure of active node a (mixed systems only).
  Index pressure_dof(Index a) const { return static_cast<Index>(active_nodes_.size()) * dim_ + a; }
  /// Nodal pressures (compression positive) per active node for the unknowns `x` of the step
  /// (dof-indexed, as passed to internal_force): p = p_start + s x_p (theory eq. 11.6).
  Vector nodal_pressure(const Vector& x) const;
  Index num_free() const { return num_free_; }
  const std::vector<Index>& active_nodes() const { return active_nodes_; }
  const std::vector<Index>& node_to_active() const { return node_to_active_; }
  const std::vector<Index>& active_cells() const { return active_cells_; }
  const std::vector<Index>& free_index() const { return free_index_; }  // dof -> free or -1
  /// Lumped nodal mass per unknown, nodal velocity and acceleration at the start of the step.
  const Vector& mass() const { return mass_; }
  const Vector& velocity() const { return velocity_; }
  const Vector& acceleration() const { return acceleration_; }
  const SparseMatrix& pattern() const { return pattern_; }
  /// The pattern's own storage, for Newton to assemble the tangent into (internal_force with
  /// tangent = &tangent_storage()): one copy of the matrix instead of two.
  SparseMatrix& tangent_storage() { return pattern_; }
  /// Fraction of each active cell's volume covered by points (0 for buffer cells).
  const std::vector<double>& cell_fill() const { return cell_fill_; }
  /// A length per active cell: its size (area or volume)^(1/dim), for penalty scaling.
  double cell_size(Index p) const { return cell_size_[p]; }
  /// sum_a N_a(x_p) u_a: a nodal vector field (dof-indexed) at point p, with the point's
  /// weights of this step (its cell's shape functions, or its wide stencil). Valid after
  /// initialise(), before the points are relocated.
  Vec3 interpolate(const MaterialPoints& points, Index p, const Vector& nodal) const;
  /// The same at x_p + offset, carried by the step's deformation: sum_a (N_a + grad N_a . offset)
  /// u_a (the weights of set_point_force_law).
  Vec3 interpolate_at(const MaterialPoints& points, Index p, const Vec3& offset,
                      const Vector& nodal) const;
  /// Per point (in the cell-sorted order of initialise()): 1 if the last internal_force returned
  /// it plastically (its return moved the trial state), 0 if its update was elastic (Newton's
  /// active set, newton.csv).
  const std::vector<char>& plastic_points() const { return plastic_; }
  /// Whether points see the grid through a stencil wider than their cell (DDMP, GIMP).
  bool wide_stencil() const { return settings_.interpolation != GridInterpolation::Standard; }

 private:
  template <class E>
  void initialise_typed(MaterialPoints& points);
  template <class E, bool Mixed>
  bool internal_force_typed(const MaterialPoints& points, const Vector& du, Vector& f_int,
                            SparseMatrix* tangent);
  /// Point p's weights in its cell (standard MPM): shape values and reference gradients.
  template <class E>
  Stencil<E::nodes, E::dim> cell_stencil(Index p) const;
  /// The volume change of the step averaged over the averaged points of active cell ci (F-bar,
  /// docs/theory.md eq. 12.1), with stencil_of(p) point p's weights over the rows of du.
  template <int NS, int Dim, class StencilOf>
  bool average_volume_change(const MaterialPoints& points, Index ci,
                             const Eigen::Matrix<double, NS, Dim>& du, StencilOf&& stencil_of,
                             AveragedVolumeChange<NS, Dim>& average) const;
  template <class E>
  void pressure_stabilisation(const MaterialPoints& points, Index ci,
                              Eigen::Matrix<double, E::nodes, E::nodes>& S) const;
  void initialise_pressure(const MaterialPoints& points);
  /// Global unknown of local unknown l of a cell or stencil with `nodes` active nodes: u of node
  /// l / dim first, then the pressures (l >= nodes * dim).
  template <class Nodes>
  Index local_dof(const Nodes& active, int nodes, int l) const {
    const int n = nodes * dim_;
    return l < n ? active[l / dim_] * dim_ + l % dim_ : pressure_dof(active[l - n]);
  }
  bool is_mixed(const MaterialPoints& points, Index p) const {
    return mixed_ && settings_.mixed[points.material[p]];
  }
  bool is_averaged(const MaterialPoints& points, Index p) const {
    return averaging_ && settings_.volume_average[points.material[p]];
  }
  template <class E>
  void convect_typed(MaterialPoints& points, const Vector& du, const Vector& velocity,
                     const Vector& acceleration, double dt, bool dynamic) const;
  template <class E>
  void empty_cell_stiffness_typed();
  /// The springs at the nodes the points barely support (eq. 6.2), added to step_blocks_.
  template <class E>
  void sparse_node_springs_typed(const MaterialPoints& points);
  /// The faces of the ghost penalty (eq. 6.3) of this step's grid, added to step_blocks_.
  void ghost_penalty_blocks(const MaterialPoints& points);
  /// f_int += the step blocks' forces on du and the tangent += their (constant) matrices.
  void add_step_blocks(const Vector& du, Vector& f_int, SparseMatrix* tangent) const;
  /// Whether point p carries a target spring (eq. 5.1) or a point force law (eq. 13.6).
  bool has_point_force(Index p) const {
    return (!target_stiffness_.empty() && target_stiffness_[p] > 0.0) ||
           (!force_law_acts_.empty() && force_law_acts_[p]);
  }
  template <int NS, int Dim, class Gradients, class Force, class Stiffness>
  void add_point_forces(Index p, const Eigen::Matrix<double, NS, 1>& N, const Gradients& dN_dX,
                        const Eigen::Matrix<double, NS, Dim>& du, bool with_tangent, Force& f,
                        Stiffness& K);
  template <class F>
  void for_each_weight(const MaterialPoints& points, Index p, F&& f) const;
  void build_gimp_stencils(const MaterialPoints& points, std::vector<char>& is_active);
  template <class E>
  void build_dual_domain_stencils(const MaterialPoints& points);
  void build_averaged_stencil_unions(const MaterialPoints& points);
  template <int Dim>
  bool wide_stencil_point_forces(const MaterialPoints& points, const Vector& du, Vector& f_int,
                                 SparseMatrix* tangent);
  void colour_active_cells();
  PointStartState start_state(const MaterialPoints& points, Index p) const;
  /// Point p's updated state at the current evaluation: written to the points only when
  /// commit_state() asks for it (`stress`: the total stress, which the mixed formulation
  /// changes; `own_volume`: the volume its own deformation gives, which differs from `volume`
  /// with a cell's volume average and stretches its domain, eq. 12.7).
  void commit(Index p, const FiniteStrainState& state, double volume, const Mat3& stress,
              double own_volume, double volume_mismatch = 0.0) const {
    plastic_[p] = state.plastic ? 1 : 0;  // each point by one thread only
    if (!commit_to_) return;
    commit_to_->volume_mismatch[p] = volume_mismatch;
    commit_to_->domain_stretch[p] *= std::pow(own_volume / volume, 1.0 / dim_);
    commit_to_->stress[p] = stress;
    commit_to_->deformation_gradient[p] = state.deformation_gradient;
    commit_to_->elastic_left_cauchy_green[p] = state.elastic_left_cauchy_green;
    commit_to_->internal[p] = state.internal;
    commit_to_->volume[p] = volume;
  }

  const Mesh& mesh_;
  const MeshTopology& topology_;
  std::vector<const Material*> materials_;
  GridSettings settings_;
  int dim_, nen_;

  std::vector<Index> active_cells_;
  std::vector<Index> cell_point_begin_, cell_point_end_;  // into the cell-sorted points
  std::vector<double> cell_fill_;
  /// Stiffnesses constant over the step on the step's displacement: the sparse-node springs
  /// (eq. 6.2) and the ghost penalty's faces (eq. 6.3); empty when both are off.
  std::vector<NodeBlock> step_blocks_;
  std::vector<double> cell_mixed_fill_;  // fraction covered by points of mixed materials
  std::vector<double> cell_size_;        // per point: size of its cell
  mutable std::vector<char> plastic_;    // per point: plastic in the last evaluation
  std::vector<Index> node_to_active_, active_nodes_;
  std::vector<std::vector<Index>> colours_;  // positions in active_cells_

  std::vector<double> shape_;      // nen per point
  std::vector<double> gradients_;  // nen * dim per point (dN/dX at the start of the step)
  Vector mass_, velocity_, acceleration_;

  std::optional<RectilinearGrid> rectilinear_;  // GIMP only

  // Wide stencils (DDMP, GIMP): each point's nodes (active ids, ascending), weights N (DDMP:
  // the cell's shape values, zero outside it) and reference gradients (dim per entry); point p
  // spans [wide_start_[p], wide_start_[p + 1]).
  std::vector<Index> wide_start_, wide_nodes_;
  std::vector<double> wide_N_, wide_gradients_;
  // With the volume average: per active cell ci, the union of its averaged points' stencils
  // (active ids, ascending) spans [union_start_[ci], union_start_[ci + 1]).
  std::vector<Index> union_start_, union_nodes_;

  std::vector<double> target_stiffness_;  // per point; empty when no point has a target
  std::vector<Vec3> target_;
  std::vector<unsigned char> target_mask_;
  std::vector<Vec3> point_reaction_;
  std::vector<char> force_law_acts_;  // per point; empty when no law is set
  std::vector<Vec3> force_law_offset_;
  PointForceLaw force_law_;

  std::vector<std::int64_t> empty_offset_;  // per active cell: its block below, or -1 (none)
  std::vector<double> empty_stiffness_;     // cell_dofs()^2 per cell with (1 - fill) > 0

  bool averaging_ = false;  // some material takes its cell's volume average (theory §12)
  // See inadmissible_point(); diagnostic state, written by const assembly helpers too.
  mutable Index inadmissible_point_ = -1;
  mutable bool inadmissible_by_stress_update_ = false;
  void note_inadmissible(Index p, bool stress_update_failed = false) const;

  // Mixed p-u (docs/theory.md §11).
  bool mixed_ = false;
  double pressure_scale_ = 1.0;  // s = G / h (eq. 11.6)
  double reference_bulk_ = 1.0;  // K of the pressure regularisation of empty space
  Vector pressure_start_;        // nodal pressure at the start of the step
  // Eq. 11.11: the last converged nodal pressure per mesh node where its support was well filled
  // (NaN elsewhere), and which active nodes of this step are so.
  std::vector<double> last_pressure_;
  std::vector<char> pressure_supported_;
  void mark_supported_pressure_nodes();
  int cell_dofs() const { return nen_ * dim_ + (mixed_ ? nen_ : 0); }

  Index num_free_ = 0;
  std::vector<Index> free_index_;
  SparseMatrix pattern_;
  std::vector<int> scatter_;  // cell_dofs()^2 per active cell: position in the values, or -1

  MaterialPoints* commit_to_ = nullptr;  // set by commit_state() only
};

}  // namespace geompm
