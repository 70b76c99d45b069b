// Shared helpers of the mesh tests: meshes to test on, random reference points, temporary
// directories.
#pragma once

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <map>
#include <random>
#include <set>
#include <string>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/mesh/structured_mesh.hpp"

namespace geompm::testing {

inline constexpr CellType all_cell_types[] = {CellType::Tri3, CellType::Tri6, CellType::Quad4,
                                              CellType::Tet4, CellType::Hex8};

/// A uniform structured mesh of [origin, origin + length] with `cells` cells per axis.
inline Mesh uniform_mesh(CellType type, int cells, const Vec3& length = Vec3(1.0, 1.0, 1.0),
                         const Vec3& origin = Vec3::Zero()) {
  StructuredMeshSpec spec;
  spec.cell_type = type;
  spec.origin = origin;
  for (int i = 0; i < cell_dimension(type); ++i) spec.axes[i] = {{length[i], cells, 1.0}};
  return generate_structured_mesh(spec);
}

/// Nodes on the boundary of a generated or imported mesh: those in any node group.
inline std::vector<char> boundary_nodes(const Mesh& mesh) {
  std::vector<char> on_boundary(mesh.nodes.size(), 0);
  for (const auto& [name, ids] : mesh.node_groups)
    for (Index n : ids) on_boundary[n] = 1;
  return on_boundary;
}

/// Moves every interior node by a random offset of up to `amplitude` per coordinate, so cells
/// become general quadrilaterals/hexahedra/triangles. For Tri6 the corners move and the
/// mid-side nodes are put back at their edge's midpoint plus `curvature` (interior edges only),
/// which makes curved cells. The boundary stays where it was.
inline void perturb_interior_nodes(Mesh& mesh, double amplitude, double curvature, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  const std::vector<char> on_boundary = boundary_nodes(mesh);
  const int dim = mesh.dim();
  const auto offset = [&](double size) {
    Vec3 d = Vec3::Zero();
    for (int i = 0; i < dim; ++i) d[i] = size * unit(rng);
    return d;
  };
  std::vector<char> is_mid(mesh.nodes.size(), 0);
  if (mesh.cell_type == CellType::Tri6)
    for (Index c = 0; c < mesh.num_cells(); ++c)
      for (int a = 3; a < 6; ++a) is_mid[mesh.cell_nodes(c)[a]] = 1;
  for (std::size_t n = 0; n < mesh.nodes.size(); ++n)
    if (!on_boundary[n] && !is_mid[n]) mesh.nodes[n] += offset(amplitude);
  if (mesh.cell_type == CellType::Tri6) {
    constexpr int ends[3][2] = {{0, 1}, {1, 2}, {2, 0}};
    std::vector<char> done(mesh.nodes.size(), 0);
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const auto nodes = mesh.cell_nodes(c);
      for (int e = 0; e < 3; ++e) {
        const Index mid = nodes[3 + e];
        if (done[mid]) continue;
        done[mid] = 1;
        mesh.nodes[mid] = 0.5 * (mesh.nodes[nodes[ends[e][0]]] + mesh.nodes[nodes[ends[e][1]]]);
        if (!on_boundary[mid]) mesh.nodes[mid] += offset(curvature);
      }
    }
  }
}

/// A mesh of the unit square/cube with distorted cells (and curved Tri6 edges).
inline Mesh distorted_mesh(CellType type, int cells, unsigned seed = 7) {
  Mesh mesh = uniform_mesh(type, cells);
  const double h = 1.0 / cells;
  const bool three_d = cell_dimension(type) == 3;
  perturb_interior_nodes(mesh, (three_d ? 0.1 : 0.15) * h, 0.04 * h, seed);
  return mesh;
}

/// A uniformly random point of the reference cell of T.
template <CellType T>
typename Element<T>::Local random_reference_point(std::mt19937& rng) {
  using Local = typename Element<T>::Local;
  constexpr bool simplex = T == CellType::Tri3 || T == CellType::Tri6 || T == CellType::Tet4;
  std::uniform_real_distribution<double> unit(simplex ? 0.0 : -1.0, 1.0);
  while (true) {
    Local xi;
    for (int i = 0; i < Element<T>::dim; ++i) xi[i] = unit(rng);
    if constexpr (T == CellType::Pyramid5) {
      xi[2] = 0.5 * (xi[2] + 1.0);
      if (Element<T>::contains(xi, 0.0)) return xi;
    } else if (!simplex || xi.sum() <= 1.0) {
      return xi;
    }
  }
}

/// Random reference points on the edges of the reference cell of `type` (between corners
/// that share an edge), as Vec3: points that lie on faces shared with neighbouring cells.
inline std::vector<Vec3> reference_edge_points(CellType type, int per_edge, std::mt19937& rng) {
  return dispatch_cell_type(type, [&](auto element) {
    using E = decltype(element);
    constexpr CellType T = cell_type_of<E>;
    constexpr bool simplex = T == CellType::Tri3 || T == CellType::Tri6 || T == CellType::Tet4;
    const int corners = simplex ? E::dim + 1 : E::nodes;
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    std::vector<Vec3> points;
    for (int a = 0; a < corners; ++a)
      for (int b = a + 1; b < corners; ++b) {
        const typename E::Local from = E::node(a), to = E::node(b);
        // Corners of [-1,1]^d share an edge when they differ in one coordinate only; a
        // pyramid's apex shares one with every corner of the base.
        const bool apex = T == CellType::Pyramid5 && b == 4;
        if (!simplex && !apex && ((from - to).array() != 0.0).count() != 1) continue;
        for (int k = 0; k < per_edge; ++k) {
          Vec3 xi = Vec3::Zero();
          xi.head<E::dim>() = from + unit(rng) * (to - from);
          points.push_back(xi);
        }
      }
    return points;
  });
}

/// Measure of the reference cell.
inline double reference_measure(CellType type) {
  switch (type) {
    case CellType::Tri3:
    case CellType::Tri6:
      return 0.5;
    case CellType::Quad4:
      return 4.0;
    case CellType::Tet4:
      return 1.0 / 6.0;
    case CellType::Hex8:
      return 8.0;
    case CellType::Pyramid5:
      return 4.0 / 3.0;  // base 4, height 1
  }
  return 0.0;
}

/// A fresh directory under the system temporary directory, removed with everything in it.
class TemporaryDirectory {
 public:
  TemporaryDirectory() {
    static std::atomic<int> counter{0};
    path_ = std::filesystem::temp_directory_path() /
            ("geompm_mesh_test_" + std::to_string(::getpid()) + "_" + std::to_string(counter++));
    std::filesystem::create_directories(path_);
  }
  ~TemporaryDirectory() {
    std::error_code ignored;
    std::filesystem::remove_all(path_, ignored);
  }
  TemporaryDirectory(const TemporaryDirectory&) = delete;
  TemporaryDirectory& operator=(const TemporaryDirectory&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// Sum of cell_measure over the mesh.
inline double total_measure(const Mesh& mesh, bool radial = false) {
  double sum = 0.0;
  for (Index c = 0; c < mesh.num_cells(); ++c) sum += cell_measure(mesh, c, radial);
  return sum;
}

}  // namespace geompm::testing

#include "geompm/mesh/gmsh_generate.hpp"
#include "geompm/mesh/gmsh_import.hpp"

namespace geompm::testing {

/// Domain of the Gmsh-generated test meshes: [0, 2] x [0, 1] (x [0, 1] in 3D).
inline const Vec3 gmsh_domain_size(2.0, 1.0, 1.0);

/// An unstructured mesh written by Gmsh (with a refined box, so cell sizes vary) and read
/// back; made once per type and kept for the rest of the test program.
inline const Mesh& gmsh_mesh(CellType type) {
  static std::map<CellType, Mesh> cache;
  auto it = cache.find(type);
  if (it != cache.end()) return it->second;
  TemporaryDirectory directory;
  const auto file = directory.path() / (std::string(to_string(type)) + ".msh");
  if (cell_dimension(type) == 2) {
    write_gmsh_rectangle(file, Vec3::Zero(), gmsh_domain_size, 0.15, type,
                         RefineBox{Vec3(0.5, 0.2, 0.0), Vec3(1.0, 0.6, 0.0)}, 0.05);
  } else {
    write_gmsh_box(file, Vec3::Zero(), gmsh_domain_size, 0.3, type,
                   RefineBox{Vec3(0.2, 0.2, 0.2), Vec3(0.6, 0.6, 0.6)}, 0.12);
  }
  return cache.emplace(type, read_gmsh_mesh(file.string(), cell_dimension(type))).first->second;
}

}  // namespace geompm::testing
