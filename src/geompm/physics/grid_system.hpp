// The computational grid of one step (seed paper Fig. 1): built from the material points at the
// start of the step (phase 1, initialise) and read back into the points at its end (phase 3,
// convect). It knows the active cells and nodes, which points lie in which cell, how each point
// sees the grid (its cell's shape functions, or a wider DDMP or GIMP stencil) and the nodal mass,
// velocity and acceleration mapped from the points (seed eq. 9). What the step solves for is
// numbered by the step's DofMap (dofs/), and every term of its equations is a Contribution
// (physics/contribution.hpp) that reads the grid.
//
// Nodal vectors passed to the grid (`nodal` arguments) hold dim components per active node,
// node-major: the displacement field's block of the step's unknowns.
#pragma once

#include <Eigen/Core>
#include <memory>
#include <span>
#include <vector>

#include "geompm/core/communicator.hpp"
#include "geompm/core/linear_algebra.hpp"
#include "geompm/interpolation/interpolation.hpp"
#include "geompm/materials/material.hpp"
#include "geompm/mesh/mesh.hpp"
#include "geompm/mesh/mesh_topology.hpp"
#include "geompm/points/material_points.hpp"

namespace geompm {

/// The step's numerical settings, read by the grid and by the contributions that need them.
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
  /// Per material index: 1 if its mixed points evaluate their material at the volume whose
  /// pressure is the field's (docs/theory.md §14) rather than at their kinematic volume.
  std::vector<char> field_pressure;
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
  /// Per mesh cell: 1 if it is an FEM cell (docs/theory.md §19), empty if none is. FEM cells are
  /// always active and count as full: their Gauss points (coupling/) fill them.
  std::vector<char> fem_cells;
};

class GridSystem {
 public:
  /// Throws std::invalid_argument if GIMP is asked for on a mesh that is not a rectilinear grid.
  GridSystem(const Mesh& mesh, const MeshTopology& topology,
             const std::vector<const Material*>& materials, const GridSettings& settings);

  /// A distributed run (docs/architecture.md, "Distributed runs"): this process holds the
  /// points of the cells `cell_part` gives it. The active cells, the cells' fill and the nodal
  /// mass, momentum and acceleration are summed over the processes, so that every process has
  /// the whole grid's (the mesh and the grid are replicated; the points are not).
  void distribute(const Communicator& communicator, std::vector<int> cell_part);
  const Communicator& communicator() const { return *communicator_; }
  /// Per mesh cell, the process that owns it (empty in a serial run).
  const std::vector<int>& cell_part() const { return cell_part_; }
  /// Whether this process owns mesh cell c (always, in a serial run).
  bool owns_cell(Index c) const {
    return cell_part_.empty() || cell_part_[c] == communicator_->rank();
  }

  // --- phase 1: initialise -------------------------------------------------------------
  /// Sorts the points by cell, finds active cells (occupied + buffer) and nodes, colours the
  /// cells, computes each point's shape functions and gradients, and maps mass, momentum and
  /// acceleration to the nodes (seed eq. 9).
  void initialise(MaterialPoints& points);

  // --- phase 3: convect ------------------------------------------------------------------
  /// Moves the points with the converged nodal displacement; the velocity and acceleration are
  /// updated from the nodal ones (FLIP increments; seed §2). Their state is committed before, by
  /// the point integrator (physics/point_integrator.hpp).
  void convect(MaterialPoints& points, const Vector& nodal_du, const Vector& nodal_velocity,
               const Vector& nodal_acceleration, double dt, bool dynamic) const;

  // --- the grid of the step ------------------------------------------------------------------
  const Mesh& mesh() const { return mesh_; }
  const MeshTopology& topology() const { return topology_; }
  const GridSettings& settings() const { return settings_; }
  const std::vector<const Material*>& materials() const { return materials_; }
  int dim() const { return dim_; }
  /// Nodes of a cell: of every cell of a uniform mesh, of the largest cell of a mixed one (the
  /// stride of the per-point shape arrays and of the per-cell blocks of the cells' terms).
  int nodes_per_cell() const { return nen_; }
  bool axisymmetric() const { return settings_.kinematics == Kinematics::Axisymmetric; }
  /// True if some material is mixed: the step has pressure unknowns.
  bool mixed() const { return mixed_; }
  bool is_mixed(const MaterialPoints& points, Index p) const {
    return mixed_ && settings_.mixed[points.material[p]];
  }
  bool is_field_pressure(const MaterialPoints& points, Index p) const {
    return is_mixed(points, p) && !settings_.field_pressure.empty() &&
           settings_.field_pressure[points.material[p]];
  }
  /// True if some material takes its cell's volume average (theory §12).
  bool averaging() const { return averaging_; }
  bool is_averaged(const MaterialPoints& points, Index p) const {
    return averaging_ && settings_.volume_average[points.material[p]];
  }
  const std::vector<Index>& active_nodes() const { return active_nodes_; }
  const std::vector<Index>& node_to_active() const { return node_to_active_; }
  const std::vector<Index>& active_cells() const { return active_cells_; }
  /// Whether mesh cell c is an FEM cell (settings().fem_cells).
  bool fem_cell(Index c) const { return !settings_.fem_cells.empty() && settings_.fem_cells[c]; }
  /// The active cells in groups no two cells of which share a node (positions in active_cells).
  const std::vector<std::vector<Index>>& colours() const { return colours_; }
  /// The points of active cell ci (points are sorted by cell): [begin, end).
  Index cell_point_begin(Index ci) const { return cell_point_begin_[ci]; }
  Index cell_point_end(Index ci) const { return cell_point_end_[ci]; }
  /// Fraction of each active cell's volume covered by points (0 for buffer cells), and by points
  /// of mixed materials.
  const std::vector<double>& cell_fill() const { return cell_fill_; }
  const std::vector<double>& cell_mixed_fill() const { return cell_mixed_fill_; }
  /// A length per point: the size (area or volume)^(1/dim) of its cell, for penalty scaling.
  double cell_size(Index p) const { return cell_size_[p]; }
  /// Lumped nodal mass per active node; nodal velocity and acceleration (nodal vectors) at the
  /// start of the step.
  const Vector& nodal_mass() const { return mass_; }
  const Vector& nodal_velocity() const { return velocity_; }
  const Vector& nodal_acceleration() const { return acceleration_; }

  // --- how points see the grid -----------------------------------------------------------------
  /// Whether points see the grid through a stencil wider than their cell (DDMP, GIMP).
  bool wide_stencil() const { return wide_stencil_; }
  /// Point p's shape values (its cell's nodes) and reference gradients (nodes x dim,
  /// column-major) in its cell; stored nodes_per_cell() and nodes_per_cell() x dim apart.
  const double* cell_shape(Index p) const { return shape_.data() + std::size_t(p) * nen_; }
  const double* cell_gradients(Index p) const {
    return gradients_.data() + std::size_t(p) * nen_ * dim_;
  }
  /// Point p's wide stencil (DDMP, GIMP): entries [begin, end) of the wide arrays, nodes active
  /// and ascending, gradients dim per entry.
  Index wide_begin(Index p) const { return wide_.start[p]; }
  Index wide_end(Index p) const { return wide_.start[p + 1]; }
  const std::vector<Index>& wide_nodes() const { return wide_.nodes; }
  const std::vector<double>& wide_values() const { return wide_.N; }
  const std::vector<double>& wide_gradients() const { return wide_.gradients; }
  /// With the volume average and a wide stencil: the active nodes (ascending) of the stencils of
  /// active cell ci's averaged points, which the average couples; empty otherwise.
  std::span<const Index> averaged_stencil_union(Index ci) const;
  /// f(active node, N_a(x_p)) over the nodes point p sees (its cell or its wide stencil).
  template <class F>
  void for_each_weight(const MaterialPoints& points, Index p, F&& f) const;
  /// sum_a N_a(x_p) u_a of a nodal vector, with the point's weights of this step. Valid after
  /// initialise(), before the points are relocated.
  Vec3 interpolate(const MaterialPoints& points, Index p, const Vector& nodal) const;

 private:
  void activate_cells(MaterialPoints& points);
  /// The shape values and gradients of the points of active cell ci, of type E, and its fill.
  template <class E>
  void shape_cell(const MaterialPoints& points, Index ci);
  template <int nen, int dim>
  void map_to_nodes(const MaterialPoints& points);
  template <int nen, int dim>
  void convect_typed(MaterialPoints& points, const Vector& du, const Vector& velocity,
                     const Vector& acceleration, double dt, bool dynamic) const;
  /// for_each_weight with the cell's node count known at compile time (0: of a mixed mesh, the
  /// point's cell's).
  template <int nen, class F>
  void for_each_weight_typed(const MaterialPoints& points, Index p, F&& f) const;
  void build_averaged_stencil_unions(const MaterialPoints& points);
  void colour_active_cells();

  void share_active_cells(std::vector<char>& is_active) const;

  const Mesh& mesh_;
  const MeshTopology& topology_;
  const Communicator* communicator_ = &serial_communicator();
  std::vector<int> cell_part_;  // per mesh cell: its process (empty: serial)
  std::vector<const Material*> materials_;
  GridSettings settings_;
  int dim_, nen_;
  bool mixed_ = false;
  bool averaging_ = false;

  std::vector<Index> active_cells_;
  std::vector<Index> cell_point_begin_, cell_point_end_;  // into the cell-sorted points
  std::vector<double> cell_fill_;
  std::vector<double> cell_mixed_fill_;  // fraction covered by points of mixed materials
  std::vector<double> cell_size_;        // per point: size of its cell
  std::vector<Index> node_to_active_, active_nodes_;
  std::vector<std::vector<Index>> colours_;  // positions in active_cells_

  std::vector<double> shape_;      // nen per point
  std::vector<double> gradients_;  // nen * dim per point (dN/dX at the start of the step)
  Vector mass_, velocity_, acceleration_;

  std::unique_ptr<Interpolation> interpolation_;
  bool wide_stencil_ = false;  // interpolation_->wide(), asked once: it is asked per point
  // Wide stencils (DDMP, GIMP; DDMP's weights are the cell's shape values, zero outside it).
  WideStencils wide_;
  // With the volume average: per active cell ci, the union of its averaged points' stencils
  // (active ids, ascending) spans [union_start_[ci], union_start_[ci + 1]).
  std::vector<Index> union_start_, union_nodes_;
};

template <class F>
void GridSystem::for_each_weight(const MaterialPoints& points, Index p, F&& f) const {
  // The one place that knows the difference, for mapping, loads and convect.
  if (wide_stencil()) {
    for (Index a = wide_.start[p]; a < wide_.start[p + 1]; ++a) f(wide_.nodes[a], wide_.N[a]);
    return;
  }
  const auto nodes = mesh_.cell_nodes(points.cell[p]);
  const double* N = shape_.data() + std::size_t(p) * nen_;
  for (std::size_t a = 0; a < nodes.size(); ++a) f(node_to_active_[nodes[a]], N[a]);
}

template <int nen, class F>
void GridSystem::for_each_weight_typed(const MaterialPoints& points, Index p, F&& f) const {
  if (wide_stencil_) {
    for (Index a = wide_.start[p]; a < wide_.start[p + 1]; ++a) f(wide_.nodes[a], wide_.N[a]);
    return;
  }
  const auto cell = mesh_.cell_nodes(points.cell[p]);
  const Index* nodes = cell.data();
  const double* N = shape_.data() + std::size_t(p) * (nen > 0 ? nen : nen_);
  const int count = nen > 0 ? nen : static_cast<int>(cell.size());
  for (int a = 0; a < count; ++a) f(node_to_active_[nodes[a]], N[a]);
}

}  // namespace geompm
