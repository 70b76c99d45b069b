#include "geompm/mesh/face_conformity.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <map>

#include "geompm/core/error.hpp"
#include "geompm/mesh/cell_faces.hpp"

namespace geompm {

namespace {

/// A face by its sorted corner nodes (the fourth is -1 for a triangle).
using FaceKey = std::array<Index, 4>;

struct FaceUse {
  int count = 0;
  Index cell = -1;  // the first cell that holds it
};

FaceKey key_of(std::span<const Index> nodes, const std::vector<int>& corners) {
  FaceKey key{-1, -1, -1, -1};
  for (std::size_t k = 0; k < corners.size(); ++k) key[k] = nodes[corners[k]];
  std::sort(key.begin(), key.begin() + static_cast<std::ptrdiff_t>(corners.size()));
  return key;
}

std::string describe_face(const Mesh& mesh, const FaceKey& face) {
  std::string out;
  for (Index n : face) {
    if (n < 0) continue;
    const Vec3& x = mesh.nodes[n];
    out += fmt::format("{}{} ({:g}, {:g}, {:g})", out.empty() ? "" : ", ", n, x[0], x[1], x[2]);
  }
  return out;
}

}  // namespace

void check_conforming_faces(const Mesh& mesh, const std::string& source) {
  if (mesh.dim() != 3) return;
  // Quadrangles and triangles meet only where the cells differ (or in pyramids): a mesh of
  // tetrahedra or of hexahedra alone is not looked at, its faces not mapped at import.
  if (!mesh.mixed() && mesh.cell_type != CellType::Pyramid5) return;
  std::map<FaceKey, FaceUse> faces;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell_nodes(c);
    for (const std::vector<int>& corners : cell_corner_faces(mesh.type_of(c))) {
      FaceUse& use = faces[key_of(nodes, corners)];
      if (use.count++ == 0) use.cell = c;
    }
  }
  // A quadrangle on the boundary (held once) with a boundary triangle on three of its corners:
  // the triangle lies in the quadrangle's plane, across it, so the two cells meet there.
  for (const auto& [quadrangle, use] : faces) {
    if (quadrangle[3] < 0 || use.count != 1) continue;
    for (int skipped = 0; skipped < 4; ++skipped) {
      FaceKey triangle{-1, -1, -1, -1};
      for (int k = 0, t = 0; k < 4; ++k)
        if (k != skipped) triangle[t++] = quadrangle[k];
      const auto found = faces.find(triangle);
      if (found == faces.end() || found->second.count != 1) continue;
      const Index a = use.cell, b = found->second.cell;
      throw InputError(
          SourceLocation{source, "", 0},
          fmt::format("is not conforming: the quadrangular face of cell {} ({}) with nodes {} "
                      "meets cell {} ({}) through a triangle on three of its corners; a "
                      "bilinear face against tetrahedra opens a gap, so expected pyramids "
                      "between hexahedra and tetrahedra (Gmsh makes them when a tetrahedral "
                      "volume meets a recombined surface; cells and nodes are counted from 0)",
                      a, to_string(mesh.type_of(a)), describe_face(mesh, quadrangle), b,
                      to_string(mesh.type_of(b))));
    }
  }
}

}  // namespace geompm
