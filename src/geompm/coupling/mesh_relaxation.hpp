// Mesh relaxation after convection in a model with an FEM region (seed §3.4, Lim et al. 2013;
// docs/theory.md §19.3): the FEM region's nodes have moved with the solution and must stay
// where they are (its Gauss points' history lives in its cells), while the MPM region's cells,
// whose points carry the history there, should return toward their least deformed shape. The
// MPM-only nodes are placed by a Laplacian mesh solve on the initial mesh (eq. 19.6): the
// displacement from the initial positions is harmonic over the MPM cells, equal to the FEM
// nodes' displacement at the interface (the seed's "artificial constraint") and zero on the
// mesh's outer boundary. Without FEM nodes that moved it is zero: the MPM mesh is reset exactly.
#pragma once

#include <Eigen/SparseCholesky>
#include <vector>

#include "geompm/core/linear_algebra.hpp"
#include "geompm/coupling/fem_region.hpp"

namespace geompm {

class MeshRelaxation {
 public:
  /// The Laplacian of eq. 19.6 on `mesh`'s cells at the region's initial nodes.
  MeshRelaxation(const Mesh& mesh, const FemRegion& region);

  /// Places the MPM-only nodes of `mesh` (its FEM nodes where the step put them).
  void relax(Mesh& mesh) const;

  /// The nodes the solve places (MPM-only and off the mesh's boundary).
  Index free_nodes() const { return static_cast<Index>(free_.size()); }

 private:
  const FemRegion& region_;
  std::vector<Index> free_;        // mesh node of each free unknown
  std::vector<Index> free_of_;     // per mesh node: its free index or -1
  std::vector<char> fem_coupled_;  // per mesh node: an FEM node a free node couples to
  SparseMatrix K_fh_;              // free x mesh nodes: the Laplacian's coupling to held nodes
  Eigen::SimplicialLDLT<SparseMatrix> K_ff_;
};

/// Per mesh node: 1 if it lies on a facet of the mesh's boundary (a facet of one cell only).
std::vector<char> boundary_nodes(const Mesh& mesh);

}  // namespace geompm
