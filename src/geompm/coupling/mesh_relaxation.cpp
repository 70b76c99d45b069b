#include "geompm/coupling/mesh_relaxation.hpp"

#include <Eigen/LU>
#include <algorithm>
#include <map>
#include <stdexcept>

#include "geompm/mesh/cell_dispatch.hpp"
#include "geompm/mesh/cell_faces.hpp"
#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"

namespace geompm {
namespace {

// The facets of a cell type by their corner nodes (local), and for tri6 the mid-side node of
// each edge.
struct FacetTable {
  const std::vector<std::vector<int>>& corners;
  std::vector<int> middle;  // per facet, or empty
};

FacetTable facets_of(CellType type) {
  if (type == CellType::Tri6) return {cell_corner_faces(type), {3, 4, 5}};
  return {cell_corner_faces(type), {}};
}

// The Laplacian's element matrix int grad N_a . grad N_b dV of cell c (plane measure).
template <class E>
Eigen::Matrix<double, E::nodes, E::nodes> laplacian(const Mesh& mesh, Index c) {
  constexpr CellType T = cell_type_of<E>;
  const NodeCoordinates<T> nodes = cell_node_coordinates<T>(mesh, c);
  Eigen::Matrix<double, E::nodes, E::nodes> K = Eigen::Matrix<double, E::nodes, E::nodes>::Zero();
  for (int q = 0; q < E::quadrature_size(); ++q) {
    const typename E::Local xi = E::quadrature_point(q);
    const auto J = jacobian<T>(nodes, xi);
    const Eigen::Matrix<double, E::nodes, E::dim> G = E::shape_gradients(xi) * J.inverse();
    K += (J.determinant() * E::quadrature_weight(q)) * (G * G.transpose());
  }
  return K;
}

}  // namespace

std::vector<char> boundary_nodes(const Mesh& mesh) {
  // A facet is keyed by its sorted corners, so a quad4's edge and a tri3's edge between the same
  // nodes are one facet (a mixed mesh's interface).
  std::map<std::vector<Index>, int> count;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell_nodes(c);
    for (const auto& facet : facets_of(mesh.type_of(c)).corners) {
      std::vector<Index> key;
      for (int a : facet) key.push_back(nodes[a]);
      std::sort(key.begin(), key.end());
      ++count[key];
    }
  }
  std::vector<char> boundary(mesh.num_nodes(), 0);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell_nodes(c);
    const FacetTable table = facets_of(mesh.type_of(c));
    for (std::size_t f = 0; f < table.corners.size(); ++f) {
      std::vector<Index> key;
      for (int a : table.corners[f]) key.push_back(nodes[a]);
      std::sort(key.begin(), key.end());
      if (count[key] != 1) continue;
      for (Index a : key) boundary[a] = 1;
      if (!table.middle.empty()) boundary[nodes[table.middle[f]]] = 1;
    }
  }
  return boundary;
}

MeshRelaxation::MeshRelaxation(const Mesh& current, const FemRegion& region)
    : region_(region), free_of_(current.num_nodes(), -1), fem_coupled_(current.num_nodes(), 0) {
  // Eq. 19.6 is posed on the initial mesh, wherever the mesh is now (a resumed run).
  Mesh mesh = current;
  mesh.nodes = region.initial_nodes();
  // Free: nodes of MPM cells that are neither FEM nodes nor on the mesh's boundary.
  const std::vector<char> boundary = boundary_nodes(mesh);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    if (region.fem_cell()[c]) continue;
    for (Index a : mesh.cell_nodes(c))
      if (!region.fem_node()[a] && !boundary[a] && free_of_[a] < 0) {
        free_of_[a] = static_cast<Index>(free_.size());
        free_.push_back(a);
      }
  }
  std::vector<Eigen::Triplet<double>> ff, fh;
  for_each_mesh_cell_typed(mesh, [&](auto element, Index c) {
    using E = decltype(element);
    if (region.fem_cell()[c]) return;
    const auto nodes = mesh.cell_nodes(c);
    const auto K = laplacian<E>(mesh, c);
    for (int a = 0; a < E::nodes; ++a) {
      const Index fa = free_of_[nodes[a]];
      if (fa < 0) continue;
      for (int b = 0; b < E::nodes; ++b) {
        const Index fb = free_of_[nodes[b]];
        if (fb >= 0) {
          ff.emplace_back(fa, fb, K(a, b));
        } else if (region.fem_node()[nodes[b]]) {
          fh.emplace_back(fa, nodes[b], K(a, b));
          fem_coupled_[nodes[b]] = 1;
        }
      }
    }
  });
  const Index n = static_cast<Index>(free_.size());
  SparseMatrix K(n, n);
  K.setFromTriplets(ff.begin(), ff.end());
  K_fh_.resize(n, mesh.num_nodes());
  K_fh_.setFromTriplets(fh.begin(), fh.end());
  if (n > 0) {
    K_ff_.compute(K);
    if (K_ff_.info() != Eigen::Success)
      throw std::runtime_error("mesh relaxation: the MPM region's Laplacian is singular");
  }
}

void MeshRelaxation::relax(Mesh& mesh) const {
  // Eq. 19.6: K_ff d_f = -K_fh d_h per component, d_h the FEM nodes' displacement since the
  // start (the boundary's is zero), then x = X + d.
  const std::vector<Vec3>& X = region_.initial_nodes();
  const Index n = static_cast<Index>(free_.size());
  for (Index a = 0; a < mesh.num_nodes(); ++a)
    if (!region_.fem_node()[a]) mesh.nodes[a] = X[a];  // the outer boundary's, and the start
  if (n == 0) return;
  for (int i = 0; i < mesh.dim(); ++i) {
    Vector d_h = Vector::Zero(mesh.num_nodes());
    for (Index a = 0; a < mesh.num_nodes(); ++a)
      if (fem_coupled_[a]) d_h(a) = mesh.nodes[a](i) - X[a](i);
    const Vector d_f = K_ff_.solve(-(K_fh_ * d_h));
    for (Index k = 0; k < n; ++k) mesh.nodes[free_[k]](i) = X[free_[k]](i) + d_f(k);
  }
}

}  // namespace geompm
