// The FEM region of the background mesh (seed §3.4, docs/theory.md §19): its cells are ordinary
// updated-Lagrangian finite elements. Each carries material points at its Gauss points, in a
// store of their own (MaterialPoints: the same state as a soil point, so that the same materials,
// kernels and outputs apply), and its nodes move with the solution, never reset: the
// configuration a step converges to is the reference of the next. The grid's displacement
// unknowns at the nodes it shares with MPM cells are the same unknowns: one system.
#pragma once

#include <vector>

#include "geompm/mesh/cell_kind.hpp"
#include "geompm/mesh/mesh.hpp"
#include "geompm/points/material_points.hpp"

namespace geompm {

class FemRegion {
 public:
  /// The FEM cells of `mesh` by `kinds` (per cell); the mesh's positions now are its initial
  /// configuration.
  FemRegion(const Mesh& mesh, const std::vector<CellKind>& kinds);

  /// The FEM cells, ascending.
  const std::vector<Index>& cells() const { return cells_; }
  /// Per mesh cell: 1 if FEM.
  const std::vector<char>& fem_cell() const { return fem_cell_; }
  /// Per mesh node: 1 if a node of an FEM cell (it moves with the solution).
  const std::vector<char>& fem_node() const { return fem_node_; }
  /// Per mesh cell, its kind.
  const std::vector<CellKind>& kinds() const { return kinds_; }
  /// The Gauss points of region cell k (cells()[k], its type's rule) are entries
  /// [gauss_begin(k), gauss_begin(k + 1)) of gauss_points(), in the rule's order; of a uniform
  /// mesh k * the rule's size.
  Index gauss_begin(std::size_t k) const { return gauss_start_[k]; }
  /// The Gauss points: `cell` is the mesh cell and `local` the quadrature point's reference
  /// coordinates, fixed.
  MaterialPoints& gauss_points() { return gauss_; }
  const MaterialPoints& gauss_points() const { return gauss_; }
  /// The mesh's node positions at the start of the analysis.
  const std::vector<Vec3>& initial_nodes() const { return initial_nodes_; }

  /// A distributed run (docs/architecture.md, "Distributed runs"): this process works on the
  /// region's cells that `cell_part` gives to `rank`, and their Gauss points are its own (those
  /// of the other cells in this store are not kept up to date). Every cell is, until this is
  /// called.
  void keep_own(const std::vector<int>& cell_part, int rank);
  /// Whether this process works on region cell k (cells()[k]).
  bool own(std::size_t k) const { return own_[k] != 0; }
  /// The Gauss points of this process's cells, ascending.
  std::vector<Index> own_gauss_points() const;

  /// Moves the FEM nodes by their converged increment (updated Lagrangian, never reset):
  /// nodal(node) the increment of mesh node `node`.
  template <class Increment>
  void move_nodes(Mesh& mesh, Increment&& nodal) const {
    for (Index a = 0; a < mesh.num_nodes(); ++a)
      if (fem_node_[a]) mesh.nodes[a] += nodal(a);
  }

 private:
  std::vector<CellKind> kinds_;
  std::vector<Index> cells_;
  std::vector<char> fem_cell_, fem_node_;
  std::vector<Index> gauss_start_;  // per region cell, and one past the last
  std::vector<char> own_;           // per region cell: 1 if this process works on it
  MaterialPoints gauss_;
  std::vector<Vec3> initial_nodes_;
};

/// The Gauss points of FEM cell c (positions and volumes in the mesh's configuration, times r
/// per radian in axisymmetry): f(q, xi, x, volume).
template <class F>
void for_each_gauss_point(const Mesh& mesh, Index c, bool axisymmetric, F&& f);

}  // namespace geompm

#include "geompm/coupling/fem_region_gauss.hpp"
