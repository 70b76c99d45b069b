#include "geompm/levelset/surface_load.hpp"

#include <Eigen/Geometry>
#include <algorithm>

#include "geompm/dofs/sparsity.hpp"
#include "geompm/mesh/element.hpp"

namespace geompm {
namespace {

/// [a]x: the matrix of a x (.) .
Mat3 cross_matrix(const Vec3& a) {
  Mat3 m;
  m << 0, -a.z(), a.y(), a.z(), 0, -a.x(), -a.y(), a.x(), 0;
  return m;
}

/// The shape functions of a cell at reference coordinates xi.
Eigen::VectorXd shape_at(CellType type, const Vec3& xi) {
  return dispatch_cell_type(type, [&](auto e) {
    using E = decltype(e);
    return Eigen::VectorXd(E::shape(xi.head<E::dim>()));
  });
}

}  // namespace

SurfaceLoad::SurfaceLoad(const GridSystem& grid, const DofMap& dofs,
                         std::vector<SurfaceFacet> facets, Kind kind, bool follower,
                         const std::function<Vec3(const Vec3&)>& value)
    : grid_(grid),
      dofs_(dofs),
      facets_(std::move(facets)),
      kind_(kind),
      follower_(follower && kind == Kind::Pressure),
      u_(dofs.find("displacement")) {
  const Mesh& mesh = grid.mesh();
  for (const SurfaceFacet& facet : facets_) {
    Loaded l;
    for (Index n : mesh.cell_nodes(facet.cell)) l.nodes.push_back(grid.node_to_active()[n]);
    const int nen = static_cast<int>(l.nodes.size());
    l.points = facet_quadrature(facet, grid.axisymmetric());
    l.N_vertex.resize(facet.vertices, nen);
    for (int k = 0; k < facet.vertices; ++k)
      l.N_vertex.row(k) = shape_at(mesh.type_of(facet.cell), facet.xi[k]).transpose();
    l.N_point.resize(Index(l.points.size()), nen);
    for (std::size_t q = 0; q < l.points.size(); ++q) {
      l.N_point.row(Index(q)) = shape_at(mesh.type_of(facet.cell), l.points[q].xi).transpose();
      l.value.push_back(value(l.points[q].x));
    }
    loaded_.push_back(std::move(l));
  }
}

void SurfaceLoad::declare_couplings(SparsityBuilder& pattern) const {
  if (!follower_) return;
  for (const Loaded& l : loaded_) {
    std::vector<Index> nodes = l.nodes;
    std::sort(nodes.begin(), nodes.end());
    pattern.couple_nodes(nodes);
  }
}

void SurfaceLoad::add_facet(std::size_t f, const Vector& du, Vector& f_ext,
                            SparseMatrix* tangent) const {
  const SurfaceFacet& facet = facets_[f];
  const Loaded& l = loaded_[f];
  const int dim = grid_.dim(), nen = static_cast<int>(l.nodes.size());
  const bool radial = grid_.axisymmetric();
  if (!follower_) {
    // Eq. 16.3 on the facets of the step's start: t = -p n or the traction, per Gauss point.
    for (std::size_t q = 0; q < l.points.size(); ++q) {
      const Vec3 t = kind_ == Kind::Pressure ? Vec3(-l.value[q](0) * facet.normal) : l.value[q];
      for (int a = 0; a < nen; ++a)
        for (int i = 0; i < dim; ++i)
          f_ext(dofs_.dof(u_, l.nodes[a], i)) += l.N_point(Index(q), a) * l.points[q].weight * t(i);
    }
    return;
  }
  // A following pressure (eq. 16.5): on the facet moved by the step, x_k = X_k + u(xi_k), its
  // area vector A (length or area times the outward normal) and, in axisymmetry, the radius of
  // each Gauss point. The Gauss weights are then the rule's shares of the facet: 1/2 or 1/3.
  std::array<Vec3, 3> x;
  for (int k = 0; k < facet.vertices; ++k) {
    x[k] = facet.x[k];
    for (int b = 0; b < nen; ++b)
      for (int i = 0; i < dim; ++i) x[k](i) += l.N_vertex(k, b) * du(dofs_.dof(u_, l.nodes[b], i));
  }
  // A and dA/dx_k (eq. 16.5).
  Vec3 A;
  std::array<Mat3, 3> dA;
  if (facet.vertices == 2) {
    const Vec3 d = x[1] - x[0];
    A = Vec3(d.y(), -d.x(), 0.0);
    dA[1] << 0, 1, 0, -1, 0, 0, 0, 0, 0;
    dA[0] = -dA[1];
  } else {
    const Vec3 a = x[1] - x[0], b = x[2] - x[0];
    A = 0.5 * a.cross(b);
    dA[1] = -0.5 * cross_matrix(b);
    dA[2] = 0.5 * cross_matrix(a);
    dA[0] = -dA[1] - dA[2];
  }
  const double share = 1.0 / double(l.points.size());
  for (std::size_t q = 0; q < l.points.size(); ++q) {
    const double p = l.value[q](0);
    double r = 1.0;
    if (radial) {
      r = 0.0;
      for (int k = 0; k < facet.vertices; ++k) r += l.points[q].lambda[k] * x[k](0);
    }
    const Vec3 t_area = -p * share * r * A;  // this Gauss point's force before N_a
    for (int a = 0; a < nen; ++a)
      for (int i = 0; i < dim; ++i)
        f_ext(dofs_.dof(u_, l.nodes[a], i)) += l.N_point(Index(q), a) * t_area(i);
    if (!tangent) continue;
    // d f_a / d du_b = -p share N_a(xi_q) [r sum_k dA/dx_k N_b(xi_k) + A (d r / d du_b)], and
    // the tangent takes -d f_ext / d du.
    for (int b = 0; b < nen; ++b) {
      Mat3 dx = Mat3::Zero();  // d (r A) / d du_b
      for (int k = 0; k < facet.vertices; ++k) {
        dx += r * l.N_vertex(k, b) * dA[k];
        if (radial) dx.col(0) += l.points[q].lambda[k] * l.N_vertex(k, b) * A;
      }
      for (int a = 0; a < nen; ++a) {
        const double scale = p * share * l.N_point(Index(q), a);  // -(-p share N_a)
        for (int i = 0; i < dim; ++i)
          for (int j = 0; j < dim; ++j)
            add_to_tangent(*tangent, dofs_, dofs_.dof(u_, l.nodes[a], i),
                           dofs_.dof(u_, l.nodes[b], j), scale * dx(i, j));
      }
    }
  }
}

Vector SurfaceLoad::force(const Vector& du, SparseMatrix* tangent) const {
  Vector f_ext = Vector::Zero(dofs_.size());
  for (std::size_t f = 0; f < facets_.size(); ++f) add_facet(f, du, f_ext, tangent);
  return f_ext;
}

bool SurfaceLoad::add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) {
  forces.external += force(du, tangent);
  return true;
}

Vec3 SurfaceLoad::resultant(const Vector& du) const {
  const Vector f = force(du);
  Vec3 sum = Vec3::Zero();
  for (std::size_t a = 0; a < grid_.active_nodes().size(); ++a)
    for (int i = 0; i < grid_.dim(); ++i) sum(i) += f(dofs_.dof(u_, Index(a), i));
  return sum;
}

}  // namespace geompm
