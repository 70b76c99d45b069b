// FEM regions beside structures (docs/theory.md §19; docs/user-guide.md "regions"): cells chosen
// by their distance from a structure (`within`, `beyond`) against the closed-form distance from a
// rectangle, the reader's errors for them, and the refusal of a structure's contact in an FEM
// cell: when the model is built (its surface lies in one) and in a run (its contact reads the
// soil in one), since contact acts on material points only.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "example_text.hpp"
#include "geompm/analysis/mesh_regions.hpp"
#include "geompm/analysis/model.hpp"
#include "geompm/core/error.hpp"
#include "geompm/io/model_reader.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

// Soil [0, 2] x [0, 1] under a row of empty cells, h = 0.25; a rigid block on the surface.
const char* kBlock = R"m(
analysis: {kinematics: plane_strain}
mesh:
  generate: {cell: quad4, origin: [0, 0], x: {length: 2, cells: 8}, y: {length: 1.25, cells: 5}}
regions:
  REGIONS
materials:
  soil: {model: linear_elastic, E: 1000, nu: 0.3, density: 0}
bodies:
  soil: {material: soil, region: {box: {min: [0, 0], max: [2, 1]}}, points_per_cell: 4}
structures:
  - {name: block, shape: {type: footing, width: 0.5, height: 0.25, position: [1.0, 1.0]}, density: 1}
phases:
  - name: hold
    duration: 1.0
    time_step: {initial: 1.0, min: 0.1, max: 1.0}
    structures:
      block: {displacement: [0, 0], rotation: 0}
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
)m";

std::string block_model(const std::string& regions, const std::string& block = "") {
  std::string text = testing::replace_once(kBlock, "REGIONS", regions);
  if (!block.empty()) text = testing::replace_once(text, "position: [1.0, 1.0]", block);
  return text;
}

// The distance from x to the block [0.75, 1.25] x [1, 1.25].
double block_distance(const Vec3& x) {
  const double dx = std::max({0.75 - x.x(), 0.0, x.x() - 1.25});
  const double dy = std::max({1.0 - x.y(), 0.0, x.y() - 1.25});
  return std::hypot(dx, dy);
}

TEST(FemRegionStructures, CellsBeyondADistanceOfAStructureAreFem) {
  const auto model = build_model(read_model_from_string(
      block_model("{far: {kind: fem, region: {box: {min: [0, 0], max: [2, 1]}}, "
                  "beyond: {structure: block, distance: 0.3}}}"),
      "block.yaml"));
  ASSERT_TRUE(model->fem);
  int fem = 0;
  for (Index c = 0; c < model->mesh.num_cells(); ++c) {
    const Vec3 x = cell_centroid(model->mesh, c);
    const bool expected = x.y() < 1.0 && block_distance(x) > 0.3;
    EXPECT_EQ(model->cell_kinds[c] == CellKind::Fem, expected) << "cell at " << x.transpose();
    fem += expected;
  }
  EXPECT_EQ(static_cast<std::size_t>(fem), model->fem->cells().size());
  EXPECT_GT(fem, 0);
  EXPECT_LT(fem, 32);
}

TEST(FemRegionStructures, CellsWithinADistanceOfAStructure) {
  const auto model = build_model(read_model_from_string(
      block_model("{near: {kind: buffer, within: {structure: block, distance: 0.3}}}"),
      "block.yaml"));
  for (Index c = 0; c < model->mesh.num_cells(); ++c) {
    const Vec3 x = cell_centroid(model->mesh, c);
    EXPECT_EQ(model->cell_kinds[c] == CellKind::Buffer, block_distance(x) <= 0.3)
        << "cell at " << x.transpose();
  }
}

TEST(FemRegionStructures, RefuseBadDistanceRegions) {
  const auto read_error = [](const std::string& regions) {
    try {
      build_model(read_model_from_string(block_model(regions), "block.yaml"));
    } catch (const InputError& e) {
      return std::string(e.what());
    }
    ADD_FAILURE() << "accepted: " << regions;
    return std::string();
  };
  EXPECT_NE(read_error("{a: {kind: fem, within: {structure: block, distance: 1}, "
                       "beyond: {structure: block, distance: 1}}}")
                .find("either within or beyond"),
            std::string::npos);
  EXPECT_NE(read_error("{a: {kind: fem, beyond: {structure: pile, distance: 1}}}")
                .find("no structure 'pile'; its structures are: block"),
            std::string::npos);
  EXPECT_NE(read_error("{a: {kind: fem}}").find("needs `region`"), std::string::npos);
  EXPECT_NE(read_error("{a: {kind: fem, beyond: {structure: block, distance: -1}}}")
                .find("regions.a.beyond.distance"),
            std::string::npos);
}

TEST(FemRegionStructures, RefuseAStructureWhoseSurfaceLiesInAnFemCell) {
  const std::string error = testing::build_error(
      block_model("{far: {kind: fem, region: {box: {min: [0, 0], max: [2, 1]}}}}",
                  "position: [1.0, 0.5]"),
      "block.yaml");
  EXPECT_NE(error.find("structures[0]: the surface of structure 'block' lies in FEM cell"),
            std::string::npos)
      << error;
}

TEST(FemRegionStructures, StopARunWhoseContactReachesAnFemCell) {
  // The soil of x < 1 is all FEM; a thin block stands in the empty cells beside it, its left
  // side 0.1 from the soil: its contact would read the soil's displacement in an FEM cell.
  std::string text = block_model("{far: {kind: fem, region: {box: {min: [0, 0], max: [1, 1]}}}}",
                                 "position: [1.15, 0.25]");
  text = testing::replace_once(text, "width: 0.5, height: 0.25", "width: 0.1, height: 0.5");
  text = testing::replace_once(text, "max: [2, 1]}}, points", "max: [1, 1]}}, points");
  try {
    testing::run_spec(read_model_from_string(text, "block.yaml"), "fem_contact");
    ADD_FAILURE() << "the run went on";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("contact surface of structure 'block' reaches FEM cell"),
              std::string::npos)
        << e.what();
  }
}

// The block pressed 1 cm (0.02 of its width) into the soil in four steps, its contact on quad4
// MPM cells (y > 0.5) over FEM cells of `far_cell` (quad4, or tri3 as the seed's pipeline model):
// the load on it at the end.
double pressed_block_load(const std::string& far_cell) {
  std::string text = block_model("{far: {kind: fem, cell: " + far_cell +
                                 ", region: {box: {min: [0, 0], max: [2, 0.5]}}}}");
  text = testing::replace_once(text, "block: {displacement: [0, 0], rotation: 0}",
                               "block: {displacement: [0, \"-0.01*t\"], rotation: 0}");
  text = testing::replace_once(text, "time_step: {initial: 1.0, min: 0.1, max: 1.0}",
                               "time_step: {initial: 0.25, min: 0.01, max: 0.25}");
  text += "output:\n  history:\n    - {quantity: reaction, structure: block, component: y}\n";
  const auto run =
      testing::run_spec(read_model_from_string(text, "block.yaml"), "pressed_block_" + far_cell);
  EXPECT_EQ(run.model->mesh.mixed(), far_cell == "tri3");
  const std::vector<double> load = run.column("reaction_block_y");
  EXPECT_EQ(load.size(), 5u);
  return load.back();
}

TEST(FemRegionStructures, ARigidBlockInContactOverTriangleFemCellsCarriesTheQuadrilateralsLoad) {
  // The contact and the MPM cells are the same; below them the tri3 cells are stiffer than the
  // quad4 cells by their discretisation only.
  const double quadrilaterals = pressed_block_load("quad4");
  const double triangles = pressed_block_load("tri3");
  std::printf("pressed block: load %.6f on quad4 FEM cells, %.6f on tri3 (%+.3f %%)\n",
              quadrilaterals, triangles, 100.0 * (triangles / quadrilaterals - 1.0));
  EXPECT_LT(quadrilaterals, -10.0);  // the drive's reaction: it holds the block down on the soil
  // Measured 1.12 %.
  EXPECT_NEAR(triangles, quadrilaterals, 0.02 * std::abs(quadrilaterals));
}

}  // namespace
}  // namespace geompm
