#include "geompm/levelset/zero_level_set.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>
#include <cmath>

#include "geompm/mesh/cell_faces.hpp"
#include "geompm/mesh/cell_geometry.hpp"

namespace geompm {
namespace {

/// A vertex of a sub-simplex or of a facet: reference and physical place, phi.
struct Vertex {
  Vec3 xi = Vec3::Zero();
  Vec3 x = Vec3::Zero();
  double phi = 0.0;
};

Vertex crossing(const Vertex& a, const Vertex& b) {
  // phi is linear along the edge and changes sign on it (a.phi > 0 >= b.phi or the reverse).
  const double t = a.phi / (a.phi - b.phi);
  return {a.xi + t * (b.xi - a.xi), a.x + t * (b.x - a.x), 0.0};
}

/// The gradient of the linear interpolant of phi on a physical simplex of dim + 1 vertices.
Vec3 linear_gradient(const Vertex* v, int dim) {
  Eigen::Matrix3d edges = Eigen::Matrix3d::Identity();
  Vec3 rise = Vec3::Zero();
  for (int k = 0; k < dim; ++k) {
    edges.row(k).head(dim) = (v[k + 1].x - v[0].x).head(dim).transpose();
    rise(k) = v[k + 1].phi - v[0].phi;
  }
  Vec3 g = Vec3::Zero();
  g.head(dim) = edges.topLeftCorner(dim, dim).partialPivLu().solve(rise.head(dim));
  return g;
}

/// The facet's area vector: (x1 - x0) rotated clockwise (2D), (x1 - x0) x (x2 - x0) / 2 (3D).
Vec3 area_vector(const Vertex* v, int vertices) {
  const Vec3 a = v[1].x - v[0].x;
  if (vertices == 2) return Vec3(a.y(), -a.x(), 0.0);
  return 0.5 * a.cross(v[2].x - v[0].x);
}

/// Appends the facet through `v` (2 or 3 vertices) unless it is degenerate (relative to `size`),
/// ordered so that its area vector points along -gradient (out of the body).
void emit(Vertex* v, int vertices, const Vec3& gradient, Index cell, double size,
          std::vector<SurfaceFacet>& out) {
  Vec3 area = area_vector(v, vertices);
  const double tiny = 1e-12 * std::pow(size, vertices - 1);
  if (!(area.norm() > tiny)) return;
  if (area.dot(gradient) > 0.0) {
    std::swap(v[0], v[1]);
    area = area_vector(v, vertices);
  }
  SurfaceFacet facet;
  facet.cell = cell;
  facet.vertices = vertices;
  for (int k = 0; k < vertices; ++k) {
    facet.x[k] = v[k].x;
    facet.xi[k] = v[k].xi;
  }
  facet.normal = area.normalized();
  out.push_back(facet);
}

double simplex_size(const Vertex* v, int n) {
  double size = 0.0;
  for (int a = 0; a < n; ++a)
    for (int b = a + 1; b < n; ++b) size = std::max(size, (v[a].x - v[b].x).norm());
  return size;
}

/// Marching triangles: the segment where the linear phi of a triangle is 0.
void cut_triangle(const Vertex (&v)[3], Index cell, std::vector<SurfaceFacet>& out) {
  Vertex ends[2];
  int found = 0;
  for (int e = 0; e < 3; ++e) {
    const Vertex &a = v[e], &b = v[(e + 1) % 3];
    if ((a.phi > 0.0) != (b.phi > 0.0)) ends[found++] = crossing(a, b);
  }
  if (found != 2) return;
  emit(ends, 2, linear_gradient(v, 2), cell, simplex_size(v, 3), out);
}

/// Marching tetrahedra: the triangle (one vertex apart) or quadrilateral (two and two, as two
/// triangles) where the linear phi of a tetrahedron is 0.
void cut_tetrahedron(const Vertex (&v)[4], Index cell, std::vector<SurfaceFacet>& out) {
  int inside[4], outside[4], n_in = 0, n_out = 0;
  for (int k = 0; k < 4; ++k) (v[k].phi > 0.0 ? inside[n_in++] : outside[n_out++]) = k;
  if (n_in == 0 || n_out == 0) return;
  const Vec3 g = linear_gradient(v, 3);
  const double size = simplex_size(v, 4);
  if (n_in == 1 || n_out == 1) {
    const int lone = n_in == 1 ? inside[0] : outside[0];
    Vertex t[3];
    int k = 0;
    for (int other = 0; other < 4; ++other)
      if (other != lone) t[k++] = crossing(v[lone], v[other]);
    emit(t, 3, g, cell, size, out);
    return;
  }
  const int a = inside[0], b = inside[1], c = outside[0], d = outside[1];
  const Vertex q[4] = {crossing(v[a], v[c]), crossing(v[a], v[d]), crossing(v[b], v[d]),
                       crossing(v[b], v[c])};
  Vertex t1[3] = {q[0], q[1], q[2]}, t2[3] = {q[0], q[2], q[3]};
  emit(t1, 3, g, cell, size, out);
  emit(t2, 3, g, cell, size, out);
}

/// The cell's vertices (nodes; centres for quad4, hex8 and pyramid5) and how its simplices use
/// them.
void cut_cell(const Mesh& mesh, Index cell, const std::vector<double>& node_phi,
              std::vector<SurfaceFacet>& out) {
  const auto nodes = mesh.cell_nodes(cell);
  bool any_in = false, any_out = false;
  for (Index n : nodes) (node_phi[n] > 0.0 ? any_in : any_out) = true;
  if (!any_in || !any_out) return;
  dispatch_cell_type(mesh.type_of(cell), [&](auto e) {
    using E = decltype(e);
    const auto vertex = [&](const Vec3& xi, double phi) {
      return Vertex{xi, map_to_physical(mesh, cell, xi), phi};
    };
    std::vector<Vertex> v;
    for (int a = 0; a < E::nodes; ++a) {
      Vec3 xi = Vec3::Zero();
      xi.head<E::dim>() = E::node(a);
      v.push_back(vertex(xi, node_phi[nodes[a]]));
    }
    const auto mean = [&](std::initializer_list<int> of) {
      Vertex m;
      for (int a : of) {
        m.xi += v[a].xi / double(of.size());
        m.phi += v[a].phi / double(of.size());
      }
      m.x = map_to_physical(mesh, cell, m.xi);
      return m;
    };
    constexpr CellType T = cell_type_of<E>;
    if constexpr (T == CellType::Tri3) {
      cut_triangle({v[0], v[1], v[2]}, cell, out);
    } else if constexpr (T == CellType::Tri6) {
      constexpr int sub[4][3] = {{0, 3, 5}, {3, 1, 4}, {5, 4, 2}, {3, 4, 5}};
      for (const auto& s : sub) cut_triangle({v[s[0]], v[s[1]], v[s[2]]}, cell, out);
    } else if constexpr (T == CellType::Quad4) {
      const Vertex centre = mean({0, 1, 2, 3});
      for (int a = 0; a < 4; ++a) cut_triangle({v[a], v[(a + 1) % 4], centre}, cell, out);
    } else if constexpr (T == CellType::Tet4) {
      cut_tetrahedron({v[0], v[1], v[2], v[3]}, cell, out);
    } else {
      // Hex8, Pyramid5: a tetrahedron from each triangular face to the centre, four from each
      // quadrangle (about its middle), so that a face shared with a neighbour is cut alike.
      Vertex centre;
      for (int a = 0; a < E::nodes; ++a) {
        centre.xi += v[a].xi / E::nodes;
        centre.phi += v[a].phi / E::nodes;
      }
      centre.x = map_to_physical(mesh, cell, centre.xi);
      for (const std::vector<int>& f : cell_corner_faces(T)) {
        if (f.size() == 3) {
          cut_tetrahedron({v[f[0]], v[f[1]], v[f[2]], centre}, cell, out);
          continue;
        }
        const Vertex middle = mean({f[0], f[1], f[2], f[3]});
        for (int k = 0; k < 4; ++k)
          cut_tetrahedron({v[f[k]], v[f[(k + 1) % 4]], middle, centre}, cell, out);
      }
    }
  });
}

/// Clips a facet's polygon (segment or triangle) to x_axis >= bound (side +1) or <= bound (-1),
/// Sutherland-Hodgman; a segment is an open polygon.
std::vector<Vertex> clip(const std::vector<Vertex>& polygon, int axis, double bound, int side) {
  if (polygon.size() < 2) return {};  // clipped away already
  const auto distance = [&](const Vertex& v) { return side * (v.x(axis) - bound); };
  const bool closed = polygon.size() > 2;
  std::vector<Vertex> kept;
  const std::size_t n = polygon.size();
  for (std::size_t k = 0; k < (closed ? n : n - 1); ++k) {
    const Vertex &a = polygon[k], &b = polygon[(k + 1) % n];
    const double da = distance(a), db = distance(b);
    if (da >= 0.0 && (closed || k == 0)) kept.push_back(a);
    if ((da >= 0.0) != (db >= 0.0)) {
      const double t = da / (da - db);
      kept.push_back({a.xi + t * (b.xi - a.xi), a.x + t * (b.x - a.x), 0.0});
    }
    if (!closed && db >= 0.0) kept.push_back(b);
  }
  return kept;
}

void clip_to_box(const SurfaceFacet& facet, const FacetBox& box, double size,
                 std::vector<SurfaceFacet>& out) {
  std::vector<Vertex> polygon;
  for (int k = 0; k < facet.vertices; ++k) polygon.push_back({facet.xi[k], facet.x[k], 0.0});
  for (int axis = 0; axis < 3; ++axis)
    if (const auto& range = box.range[axis]) {
      polygon = clip(polygon, axis, (*range)[0], +1);
      polygon = clip(polygon, axis, (*range)[1], -1);
    }
  // The clipped polygon keeps the facet's orientation: emit() along -normal keeps it too.
  if (facet.vertices == 2) {
    if (polygon.size() == 2) emit(polygon.data(), 2, -facet.normal, facet.cell, size, out);
    return;
  }
  for (std::size_t k = 1; k + 1 < polygon.size(); ++k) {
    Vertex t[3] = {polygon[0], polygon[k], polygon[k + 1]};
    emit(t, 3, -facet.normal, facet.cell, size, out);
  }
}

}  // namespace

double SurfaceFacet::measure() const {
  if (vertices == 2) return (x[1] - x[0]).norm();
  return 0.5 * (x[1] - x[0]).cross(x[2] - x[0]).norm();
}

std::vector<FacetPoint> facet_quadrature(const SurfaceFacet& facet, bool axisymmetric) {
  std::vector<FacetPoint> rule;
  const double measure = facet.measure();
  if (facet.vertices == 2) {
    const double offset = 0.5 / std::sqrt(3.0);
    for (const double s : {0.5 - offset, 0.5 + offset})
      rule.push_back({{1.0 - s, s, 0.0}, Vec3::Zero(), Vec3::Zero(), 0.5 * measure});
  } else {
    for (int k = 0; k < 3; ++k) {
      FacetPoint point;
      point.lambda = {1.0 / 6.0, 1.0 / 6.0, 1.0 / 6.0};
      point.lambda[k] = 2.0 / 3.0;
      point.weight = measure / 3.0;
      rule.push_back(point);
    }
  }
  for (FacetPoint& point : rule) {
    for (int k = 0; k < facet.vertices; ++k) {
      point.x += point.lambda[k] * facet.x[k];
      point.xi += point.lambda[k] * facet.xi[k];
    }
    // Loads are per radian in axisymmetry: the ring's length per radian is r ds.
    if (axisymmetric) point.weight *= point.x(0);
  }
  return rule;
}

std::vector<SurfaceFacet> zero_level_set(const Mesh& mesh, const std::vector<double>& node_phi,
                                         const std::vector<Index>& cells, const FacetBox* box) {
  std::vector<SurfaceFacet> facets;
  const auto cut = [&](Index c) { cut_cell(mesh, c, node_phi, facets); };
  if (cells.empty()) {
    for (Index c = 0; c < mesh.num_cells(); ++c) cut(c);
  } else {
    for (Index c : cells) cut(c);
  }
  if (!box) return facets;
  std::vector<SurfaceFacet> clipped;
  for (const SurfaceFacet& facet : facets) {
    const auto [lower, upper] = cell_bounding_box(mesh, facet.cell);
    clip_to_box(facet, *box, (upper - lower).norm(), clipped);
  }
  return clipped;
}

void move_facets(std::vector<SurfaceFacet>& facets, const GridSystem& grid, const Vector& nodal) {
  const Mesh& mesh = grid.mesh();
  const int dim = grid.dim();
  for (SurfaceFacet& facet : facets) {
    const auto nodes = mesh.cell_nodes(facet.cell);
    Vertex v[3];
    for (int k = 0; k < facet.vertices; ++k) {
      const Eigen::VectorXd N = dispatch_cell_type(mesh.type_of(facet.cell), [&](auto e) {
        using E = decltype(e);
        return Eigen::VectorXd(E::shape(facet.xi[k].head<E::dim>()));
      });
      v[k].x = facet.x[k];
      for (std::size_t a = 0; a < nodes.size(); ++a)
        for (int i = 0; i < dim; ++i)
          v[k].x(i) += N(Index(a)) * nodal(grid.node_to_active()[nodes[a]] * dim + i);
      facet.x[k] = v[k].x;
    }
    const Vec3 area = area_vector(v, facet.vertices);
    if (area.norm() > 0.0) facet.normal = area.normalized();
  }
}

std::vector<SurfaceFacet> zero_level_set(const LevelSet& phi, const FacetBox* box) {
  const GridSystem& grid = phi.grid();
  const Mesh& mesh = grid.mesh();
  std::vector<double> node_phi(mesh.num_nodes(), LevelSet::outside);
  for (std::size_t a = 0; a < grid.active_nodes().size(); ++a)
    node_phi[grid.active_nodes()[a]] = phi.nodal()[a];
  // Cells whose nodes are all active: a facet's load goes to its cell's nodes.
  std::vector<Index> cells;
  for (Index c : grid.active_cells()) {
    bool all = true;
    for (Index n : mesh.cell_nodes(c)) all = all && grid.node_to_active()[n] >= 0;
    if (all) cells.push_back(c);
  }
  if (cells.empty()) return {};
  return zero_level_set(mesh, node_phi, cells, box);
}

}  // namespace geompm
