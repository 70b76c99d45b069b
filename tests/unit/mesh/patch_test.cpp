// Patch test: on distorted and unstructured meshes, a linear displacement field u = A x + c
// given at the nodes is interpolated exactly, and its gradient (mapped from the reference cell
// with the inverse Jacobian) is the constant A. Isoparametric elements of every type must pass.
#include <gtest/gtest.h>

#include <random>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/point_locator.hpp"
#include "geompm/mesh/structured_mesh.hpp"
#include "mesh_test_support.hpp"

namespace geompm {
namespace {

using testing::all_cell_types;

template <CellType T>
struct LinearField {
  static constexpr int dim = Element<T>::dim;
  using Local = typename Element<T>::Local;
  Eigen::Matrix<double, dim, dim> gradient;
  Local offset;

  explicit LinearField(std::mt19937& rng) {
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    gradient = gradient.NullaryExpr([&] { return unit(rng); });
    offset = offset.NullaryExpr([&] { return unit(rng); });
  }

  /// Checks value and gradient of the interpolated field in cell c at xi.
  void check(const Mesh& mesh, Index c, const Local& xi) const {
    const NodeCoordinates<T> nodes = cell_node_coordinates<T>(mesh, c);
    const NodeCoordinates<T> nodal_u = (gradient * nodes).colwise() + offset;
    const Jacobian<T> J = jacobian<T>(nodes, xi);
    // dN/dx = dN/dxi J^-1 (row a of the gradients matrix is dN_a/dxi).
    const typename Element<T>::Gradients dn_dx = Element<T>::shape_gradients(xi) * J.inverse();
    const Eigen::Matrix<double, dim, dim> interpolated_gradient = nodal_u * dn_dx;
    EXPECT_LT((interpolated_gradient - gradient).norm(), 1e-10 * gradient.norm())
        << to_string(T) << " cell " << c << " xi " << xi.transpose();
    const Local x = map_to_physical<T>(nodes, xi);
    const Local u = nodal_u * Element<T>::shape(xi);
    EXPECT_LT((u - (gradient * x + offset)).norm(), 1e-12) << to_string(T) << " cell " << c;
  }
};

/// Random points of every cell, chosen in the reference cell.
void patch_test_at_reference_points(const Mesh& mesh, unsigned seed) {
  dispatch_cell_type(mesh.cell_type, [&](auto element) {
    constexpr CellType T = cell_type_of<decltype(element)>;
    std::mt19937 rng(seed);
    const LinearField<T> field(rng);
    for (Index c = 0; c < mesh.num_cells(); ++c)
      for (int k = 0; k < 4; ++k) field.check(mesh, c, testing::random_reference_point<T>(rng));
  });
}

/// Random physical points of the domain, found with the point locator.
void patch_test_at_physical_points(const Mesh& mesh, const Vec3& lower, const Vec3& upper,
                                   unsigned seed) {
  const PointLocator locator(mesh);
  dispatch_cell_type(mesh.cell_type, [&](auto element) {
    constexpr CellType T = cell_type_of<decltype(element)>;
    std::mt19937 rng(seed);
    const LinearField<T> field(rng);
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    for (int k = 0; k < 2000; ++k) {
      Vec3 x = Vec3::Zero();
      for (int i = 0; i < mesh.dim(); ++i) x[i] = lower[i] + unit(rng) * (upper[i] - lower[i]);
      const auto location = locator.locate(x);
      ASSERT_TRUE(location.has_value()) << x.transpose();
      field.check(mesh, location->cell, location->xi.head<Element<T>::dim>());
    }
  });
}

TEST(PatchTest, DistortedStructuredMeshes) {
  for (CellType type : all_cell_types) {
    const Mesh mesh = testing::distorted_mesh(type, cell_dimension(type) == 2 ? 6 : 3, 17);
    ASSERT_NO_THROW(validate_mesh(mesh, "distorted"));
    // The distortion must be real: some cell is far from affine.
    double least = 1.0;
    for (Index c = 0; c < mesh.num_cells(); ++c)
      least = std::min(least, cell_min_relative_jacobian(mesh, c));
    if (type != CellType::Tri3 && type != CellType::Tet4) {
      EXPECT_LT(least, 0.95);
    }
    SCOPED_TRACE(to_string(type));
    patch_test_at_reference_points(mesh, 5);
    patch_test_at_physical_points(mesh, Vec3::Zero(), Vec3::Ones(), 6);
  }
}

TEST(PatchTest, UnstructuredGmshMeshes) {
  for (CellType type : {CellType::Tri3, CellType::Tri6, CellType::Quad4, CellType::Tet4}) {
    const Mesh& mesh = testing::gmsh_mesh(type);
    SCOPED_TRACE(to_string(type));
    patch_test_at_reference_points(mesh, 7);
    patch_test_at_physical_points(mesh, Vec3::Zero(), testing::gmsh_domain_size, 8);
  }
}

TEST(PatchTest, MixedQuadAndTriangleMesh) {
  // A generated 6 x 6 mesh, rectangles left of x = 0.5 split in tri3: one linear field over both
  // kinds of cell, located across their interface.
  StructuredMeshSpec spec;
  spec.cell_type = CellType::Quad4;
  spec.axes[0] = {{1.0, 6, 1.0}};
  spec.axes[1] = {{1.0, 6, 1.0}};
  spec.cell_type_at = [](const Vec3& x) { return x.x() < 0.5 ? CellType::Tri3 : CellType::Quad4; };
  const Mesh mesh = generate_structured_mesh(spec);
  ASSERT_TRUE(mesh.mixed());
  ASSERT_NO_THROW(validate_mesh(mesh, "mixed"));
  EXPECT_EQ(mesh.num_cells(), 18 * 2 + 18);
  EXPECT_NEAR(testing::total_measure(mesh), 1.0, 1e-14);
  Eigen::Matrix2d A;
  A << 0.3, -1.2, 0.7, 0.4;
  const Eigen::Vector2d offset(0.1, -0.5);
  const PointLocator locator(mesh);
  std::mt19937 rng(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int in_triangles = 0;
  for (int k = 0; k < 2000; ++k) {
    const Vec3 x(unit(rng), unit(rng), 0.0);
    const auto location = locator.locate(x);
    ASSERT_TRUE(location.has_value()) << x.transpose();
    in_triangles += mesh.type_of(location->cell) == CellType::Tri3;
    dispatch_cell_type(mesh.type_of(location->cell), [&](auto element) {
      using E = decltype(element);
      constexpr CellType T = cell_type_of<E>;
      if constexpr (E::dim != 2)
        return;  // a 2D mesh: the 3D types are not instantiated
      else {
        const NodeCoordinates<T> nodes = cell_node_coordinates<T>(mesh, location->cell);
        const NodeCoordinates<T> nodal_u = (A * nodes).colwise() + offset;
        const typename E::Local xi = location->xi.template head<2>();
        EXPECT_LT((nodal_u * E::shape(xi) - (A * x.head<2>() + offset)).norm(), 1e-12);
        const auto J = jacobian<T>(nodes, xi);
        EXPECT_LT((nodal_u * (E::shape_gradients(xi) * J.inverse()) - A).norm(), 1e-12);
      }
    });
  }
  EXPECT_GT(in_triangles, 800);
  EXPECT_LT(in_triangles, 1200);
}

TEST(PatchTest, FailsForAFieldThatIsNotLinear) {
  // The check above is not vacuous: a quadratic field is not reproduced by Quad4.
  const Mesh mesh = testing::distorted_mesh(CellType::Quad4, 2, 17);
  const NodeCoordinates<CellType::Quad4> nodes = cell_node_coordinates<CellType::Quad4>(mesh, 0);
  const Eigen::Matrix<double, 1, 4> nodal_u = nodes.row(0).array().square();  // u = x^2
  const Eigen::Vector2d xi(0.3, -0.2);
  const auto J = jacobian<CellType::Quad4>(nodes, xi);
  const double du_dx =
      (nodal_u * Element<CellType::Quad4>::shape_gradients(xi) * J.inverse())(0, 0);
  const double x = map_to_physical<CellType::Quad4>(nodes, xi)[0];
  EXPECT_GT(std::abs(du_dx - 2.0 * x), 1e-6);
}

}  // namespace
}  // namespace geompm
