// Recognising a rectilinear grid (the structure GIMP needs, docs/theory.md §9): graded meshes of
// the built-in generator are recognised with their grid lines and cell indices, whatever the
// node numbering; meshes that are not axis-aligned tensor grids are rejected with a reason.
#include "geompm/mesh/rectilinear_grid.hpp"

#include <gtest/gtest.h>

#include <algorithm>

#include "geompm/mesh/structured_mesh.hpp"

namespace geompm {
namespace {

StructuredMeshSpec graded_spec(CellType type) {
  StructuredMeshSpec spec;
  spec.cell_type = type;
  spec.origin = Vec3(-1.0, 2.0, 0.5);
  spec.axes[0] = {{1.0, 3, 2.0}, {2.0, 2, 1.0}};
  spec.axes[1] = {{4.0, 4, 0.25}};
  spec.axes[2] = {{1.5, 2, 3.0}};
  return spec;
}

void expect_grid_matches(const Mesh& mesh, const StructuredMeshSpec& spec) {
  std::string why;
  const auto grid = find_rectilinear_grid(mesh, why);
  ASSERT_TRUE(grid) << why;
  const int dim = mesh.dim();
  EXPECT_EQ(grid->dim, dim);
  for (int d = 0; d < dim; ++d) {
    const auto expected = axis_coordinates(spec.origin(d), spec.axes[d]);
    ASSERT_EQ(grid->lines[d].size(), expected.size());
    for (std::size_t i = 0; i < expected.size(); ++i)
      EXPECT_NEAR(grid->lines[d][i], expected[i], 1e-12);
  }
  // Every cell lies between the lines of its index, and the index maps back to the cell.
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto& ijk = grid->cell_index[c];
    EXPECT_EQ(grid->cell(ijk[0], ijk[1], ijk[2]), c);
    for (Index n : mesh.cell_nodes(c))
      for (int d = 0; d < dim; ++d) {
        const double x = mesh.nodes[n](d);
        EXPECT_TRUE(x == grid->lines[d][ijk[d]] || x == grid->lines[d][ijk[d] + 1]);
      }
  }
  for (Index n = 0; n < mesh.num_nodes(); ++n) {
    int ijk[3] = {0, 0, 0};
    for (int d = 0; d < dim; ++d)
      ijk[d] = static_cast<int>(
          std::find(grid->lines[d].begin(), grid->lines[d].end(), mesh.nodes[n](d)) -
          grid->lines[d].begin());
    EXPECT_EQ(grid->node(ijk[0], ijk[1], ijk[2]), n);
  }
}

TEST(RectilinearGrid, RecognisesGradedQuadAndHexMeshes) {
  for (CellType type : {CellType::Quad4, CellType::Hex8}) {
    const auto spec = graded_spec(type);
    expect_grid_matches(generate_structured_mesh(spec), spec);
  }
}

TEST(RectilinearGrid, IndependentOfNodeAndCellNumbering) {
  const auto spec = graded_spec(CellType::Quad4);
  Mesh mesh = generate_structured_mesh(spec);
  // Reverse the node numbering and the cell order, and rotate each cell's node list.
  const Index n = mesh.num_nodes();
  std::reverse(mesh.nodes.begin(), mesh.nodes.end());
  for (Index& node : mesh.connectivity) node = n - 1 - node;
  std::vector<Index> cells;
  for (Index c = mesh.num_cells() - 1; c >= 0; --c) {
    const auto nodes = mesh.cell_nodes(c);
    for (int a = 0; a < 4; ++a) cells.push_back(nodes[(a + 1) % 4]);
  }
  mesh.connectivity = cells;
  expect_grid_matches(mesh, spec);
}

TEST(RectilinearGrid, RejectsOtherMeshes) {
  std::string why;
  auto spec = graded_spec(CellType::Tri3);
  EXPECT_FALSE(find_rectilinear_grid(generate_structured_mesh(spec), why));
  EXPECT_NE(why.find("tri3 cells"), std::string::npos) << why;

  // A node moved off its grid line: a skewed quadrilateral.
  spec.cell_type = CellType::Quad4;
  Mesh skewed = generate_structured_mesh(spec);
  skewed.nodes[7].x() += 0.1;
  EXPECT_FALSE(find_rectilinear_grid(skewed, why));
  EXPECT_NE(why.find("complete grid of axis-aligned lines"), std::string::npos) << why;

  // An L-shaped mesh: a grid with one cell removed is not complete.
  Mesh l_shape = generate_structured_mesh(spec);
  l_shape.connectivity.resize(l_shape.connectivity.size() - 4);
  EXPECT_FALSE(find_rectilinear_grid(l_shape, why));
  EXPECT_NE(why.find("cells where a complete grid"), std::string::npos) << why;
}

}  // namespace
}  // namespace geompm
