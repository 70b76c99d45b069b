// End-to-end: malformed models whose fault shows only when the model is built (the reader alone
// accepts them), bad command lines and a bad plot request. For each: the exit code, that stderr
// names the model file (with the key path and line where the model reader gives one) and says
// what was expected, and that bad input never half-writes output: the directory given with -o is
// not created, nor is any other file.
//
// The meshes are Gmsh .msh 4.1 ASCII files written here by hand: two quadrangles (or triangles)
// of the square [0, 2] x [0, 1] with the cell group "soil" and the boundaries "bottom", "left"
// and "top" (no "right").
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <filesystem>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "cli_support.hpp"

namespace {

namespace fs = std::filesystem;

using namespace geompm::testing;

// ---------------------------------------------------------------------------------------------
// Where the model reader says a problem is.

/// 1-based line of the first occurrence of `marker` in `text` (0 if absent, which fails).
int line_of(const std::string& text, const std::string& marker) {
  const std::size_t at = text.find(marker);
  EXPECT_NE(at, std::string::npos) << "marker not in text: " << marker;
  if (at == std::string::npos) return 0;
  return 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
}

/// "model.yaml:12: bodies.soil.region: " for the line of `marker` in `model`.
std::string where(const std::string& model, const std::string& marker, const std::string& key) {
  return "model.yaml:" + std::to_string(line_of(model, marker)) + ": " + key + ": ";
}

// ---------------------------------------------------------------------------------------------
// Gmsh .msh 4.1 ASCII files, written by hand: every node in the block of the one surface, line
// elements on the boundary curves so that Gmsh knows the nodes of each physical curve.

struct Msh {
  std::vector<std::array<double, 2>> nodes;  // node k has tag k + 1
  int gmsh_type = 3;                         // 2: 3-node triangle, 3: 4-node quadrangle
  std::vector<std::vector<int>> cells;       // node tags
  std::vector<std::pair<std::string, std::vector<std::pair<int, int>>>> boundaries;
  std::string cell_group = "soil";
};

std::string msh_text(const Msh& m) {
  const int curves = static_cast<int>(m.boundaries.size());
  double lo_x = 1e300, lo_y = 1e300, hi_x = -1e300, hi_y = -1e300;
  for (const auto& [x, y] : m.nodes) {
    lo_x = std::min(lo_x, x), lo_y = std::min(lo_y, y);
    hi_x = std::max(hi_x, x), hi_y = std::max(hi_y, y);
  }
  std::ostringstream bbox;
  bbox << lo_x << " " << lo_y << " 0 " << hi_x << " " << hi_y << " 0";

  std::ostringstream s;
  s << "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n";
  s << "$PhysicalNames\n" << curves + 1 << "\n";
  for (int k = 0; k < curves; ++k) s << "1 " << k + 1 << " \"" << m.boundaries[k].first << "\"\n";
  s << "2 " << curves + 1 << " \"" << m.cell_group << "\"\n$EndPhysicalNames\n";
  s << "$Entities\n0 " << curves << " 1 0\n";
  for (int k = 0; k < curves; ++k) s << k + 1 << " " << bbox.str() << " 1 " << k + 1 << " 0\n";
  s << "1 " << bbox.str() << " 1 " << curves + 1 << " 0\n$EndEntities\n";

  const std::size_t n = m.nodes.size();
  s << "$Nodes\n1 " << n << " 1 " << n << "\n2 1 0 " << n << "\n";
  for (std::size_t k = 0; k < n; ++k) s << k + 1 << "\n";
  for (const auto& [x, y] : m.nodes) s << x << " " << y << " 0\n";
  s << "$EndNodes\n";

  std::size_t elements = m.cells.size();
  for (const auto& b : m.boundaries) elements += b.second.size();
  s << "$Elements\n" << curves + 1 << " " << elements << " 1 " << elements << "\n";
  std::size_t tag = 0;
  for (int k = 0; k < curves; ++k) {
    s << "1 " << k + 1 << " 1 " << m.boundaries[k].second.size() << "\n";
    for (const auto& [a, b] : m.boundaries[k].second) s << ++tag << " " << a << " " << b << "\n";
  }
  s << "2 1 " << m.gmsh_type << " " << m.cells.size() << "\n";
  for (const auto& cell : m.cells) {
    s << ++tag;
    for (int node : cell) s << " " << node;
    s << "\n";
  }
  s << "$EndElements\n";
  return s.str();
}

/// 4 --- 5 --- 6
/// |     |     |      two unit quadrangles, counter-clockwise
/// 1 --- 2 --- 3
Msh two_quads() {
  Msh m;
  m.nodes = {{0, 0}, {1, 0}, {2, 0}, {0, 1}, {1, 1}, {2, 1}};
  m.cells = {{1, 2, 5, 4}, {2, 3, 6, 5}};
  m.boundaries = {{"bottom", {{1, 2}, {2, 3}}}, {"left", {{1, 4}}}, {"top", {{4, 5}, {5, 6}}}};
  return m;
}

/// An L: the two quadrangles above and a third on top of the left one; the notch
/// [1, 2] x [1, 2] is inside the mesh's bounding box but in no cell.
Msh l_shape() {
  Msh m = two_quads();
  m.nodes.push_back({0, 2});  // 7
  m.nodes.push_back({1, 2});  // 8
  m.cells.push_back({4, 5, 8, 7});
  m.boundaries = {{"bottom", {{1, 2}, {2, 3}}}, {"left", {{1, 4}, {4, 7}}}};
  return m;
}

// ---------------------------------------------------------------------------------------------
// A small model on an imported mesh; each test changes one part.

struct ModelParts {
  std::string kinematics = "plane_strain";
  std::string mesh = "mesh: {file: mesh.msh}";
  std::string region = "{group: soil}";
  std::string body_extra;   // more keys of bodies.soil, indented by 4
  std::string more_bodies;  // more bodies, indented by 2
  std::string point_sets;   // the whole section
  std::string gravity = "[0, -10]";
  std::string fixities =
      "      - {boundary: bottom, fix: all}\n"
      "      - {boundary: left, fix: normal}\n";
  std::string output;    // the whole section
  std::string numerics;  // the whole section
};

std::string model_text(const ModelParts& p) {
  return "# A small model on an imported mesh (test_cli_errors.cpp).\n"
         "analysis: {kinematics: " +
         p.kinematics + "}\n" + p.mesh +
         "\n"
         "materials:\n"
         "  soil: {model: linear_elastic, E: 1000, nu: 0.3, density: 1}\n"
         "bodies:\n"
         "  soil:\n"
         "    material: soil\n"
         "    region: " +
         p.region + "\n" + p.body_extra + p.more_bodies + p.point_sets +
         "phases:\n"
         "  - name: gravity\n"
         "    time_step: 0.5\n"
         "    gravity: {acceleration: " +
         p.gravity +
         "}\n"
         "    fixities:\n" +
         p.fixities + p.output + p.numerics;
}

class CliErrors : public GeompmRunTest<> {
 protected:
  /// `geompm check model.yaml` and `geompm run -q -o out model.yaml` both reject the model as bad
  /// input (exit 2) with the same message, print nothing on stdout and write nothing (no `out`,
  /// no default `model_results`, no file at all). Returns the message.
  std::string expect_input_error() {
    const auto check = geompm({"check", "model.yaml"});
    EXPECT_TRUE(check.exited && check.exit_code == 2) << "geompm check: " << describe(check);
    EXPECT_EQ(check.out, "") << "geompm check: " << describe(check);

    const auto run = geompm({"run", "-q", "-o", "out", "model.yaml"});
    EXPECT_TRUE(run.exited && run.exit_code == 2) << "geompm run: " << describe(run);
    EXPECT_EQ(run.out, "") << "geompm run: " << describe(run);
    EXPECT_TRUE(run.err.rfind("error: ", 0) == 0) << describe(run);
    EXPECT_EQ(run.err, check.err) << "check and run should report the same problem";
    EXPECT_FALSE(fs::exists(work() / "out")) << "bad input created the output directory";
    for (const auto& name : unexpected_files()) ADD_FAILURE() << "bad input wrote " << name;
    return run.err;
  }
};

// The model the error tests start from is valid: each test fails for its own fault only.
TEST_F(CliErrors, BaselineModelIsValidAndRuns) {
  write("mesh.msh", msh_text(two_quads()));
  write("model.yaml", model_text({}));
  const auto check = geompm({"check", "model.yaml"});
  ASSERT_TRUE(check.exited && check.exit_code == 0) << describe(check);
  EXPECT_TRUE(Contains(check.out, "model is valid"));
  EXPECT_TRUE(Contains(check.out, "2 quad4 cells, 6 nodes"));
  const auto run = geompm({"run", "-q", "-t", "1", "-o", "out", "model.yaml"});
  ASSERT_TRUE(run.exited && run.exit_code == 0) << describe(run);
  EXPECT_TRUE(fs::is_regular_file(work() / "out" / "history.csv"));

  write("mesh.msh", msh_text(l_shape()));
  const auto l_check = geompm({"check", "model.yaml"});
  ASSERT_TRUE(l_check.exited && l_check.exit_code == 0) << describe(l_check);
  EXPECT_TRUE(Contains(l_check.out, "3 quad4 cells, 8 nodes"));
}

TEST_F(CliErrors, InvertedCellInImportedMesh) {
  Msh mesh = two_quads();
  mesh.cells[0] = {1, 4, 5, 2};  // clockwise
  write("mesh.msh", msh_text(mesh));
  write("model.yaml", model_text({}));
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, "mesh.msh: cell 0 (quad4) is inverted or degenerate"));
  EXPECT_TRUE(Contains(err, "expected a positive Jacobian throughout the cell"));
  EXPECT_TRUE(Contains(err, "counter-clockwise"));
}

TEST_F(CliErrors, DegenerateCellInImportedMesh) {
  Msh mesh;
  mesh.nodes = {{0, 0}, {1, 0}, {2, 0}, {1, 1}};
  mesh.gmsh_type = 2;
  mesh.cells = {{1, 2, 4}, {1, 2, 3}};  // the second has three nodes on a line: zero area
  mesh.boundaries = {{"bottom", {{1, 2}, {2, 3}}}, {"left", {{1, 4}}}};
  write("mesh.msh", msh_text(mesh));
  write("model.yaml", model_text({}));
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, "mesh.msh: cell 1 (tri3) is inverted or degenerate"));
  EXPECT_TRUE(Contains(err, "expected a positive Jacobian throughout the cell"));
}

TEST_F(CliErrors, MeshFileDoesNotExist) {
  ModelParts parts;
  parts.mesh = "mesh: {file: meshes/nowhere.msh}";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(
      err, where(model, "mesh: {file", "mesh.file") + "mesh file 'meshes/nowhere.msh' not found"));
  EXPECT_TRUE(Contains(err, (work() / "meshes" / "nowhere.msh").string()));
  EXPECT_TRUE(Contains(err, "a relative path starts at the model file's directory"));
}

TEST_F(CliErrors, MeshFileIsNotAMesh) {
  write("garbage.msh", "These are the minutes of the site meeting, not a mesh.\n1 2 3\n");
  ModelParts parts;
  parts.mesh = "mesh: {file: garbage.msh}";
  write("model.yaml", model_text(parts));
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, "garbage.msh: cannot be read as a Gmsh mesh"));
  EXPECT_TRUE(Contains(err, "expected a .msh file"));
}

TEST_F(CliErrors, MeshOfTheWrongDimension) {
  write("mesh.msh", msh_text(two_quads()));
  ModelParts parts;
  parts.kinematics = "3d";
  parts.gravity = "[0, 0, -10]";
  write("model.yaml", model_text(parts));
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, "mesh.msh: has no 3D cells"));
  EXPECT_TRUE(
      Contains(err, "expected tetrahedra (tet4), hexahedra (hex8) and pyramids (pyramid5)"));
}

TEST_F(CliErrors, BodyBoxReachesOutsideTheMesh) {
  write("mesh.msh", msh_text(two_quads()));
  ModelParts parts;
  parts.region = "{box: {min: [0, 0], max: [3, 1]}}";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, where(model, "region: {box", "bodies.soil.region") +
                                "body 'soil' reaches outside the mesh"));
  EXPECT_TRUE(Contains(err, "its region spans [0, 3] in x but the mesh spans [0, 2]"));
}

TEST_F(CliErrors, BodyPolygonOutsideTheMesh) {
  write("mesh.msh", msh_text(two_quads()));
  ModelParts parts;
  parts.region = "{polygon: [[5, 5], [6, 5], [6, 6]]}";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, where(model, "region: {polygon", "bodies.soil.region") +
                                "body 'soil' reaches outside the mesh"));
  EXPECT_TRUE(Contains(err, "the mesh spans [0, 2]"));
}

// Inside the mesh's bounding box, but in the notch of the L where there is no cell.
TEST_F(CliErrors, BodyPolygonInNoCell) {
  write("mesh.msh", msh_text(l_shape()));
  ModelParts parts;
  parts.region = "{polygon: [[1.2, 1.2], [1.8, 1.2], [1.8, 1.8], [1.2, 1.8]]}";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, where(model, "region: {polygon", "bodies.soil.region") +
                                "body 'soil' has no material points"));
  EXPECT_TRUE(Contains(err, "its region holds no seeding position of any cell"));
}

TEST_F(CliErrors, BodyRegionGroupNotInTheMesh) {
  write("mesh.msh", msh_text(two_quads()));
  ModelParts parts;
  parts.region = "{group: clay}";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(
      err, where(model, "region: {group", "bodies.soil.region") + "the mesh has no region 'clay'"));
  EXPECT_TRUE(Contains(err, "its regions are: soil"));
}

TEST_F(CliErrors, OverlappingBodies) {
  write("mesh.msh", msh_text(two_quads()));
  ModelParts parts;
  parts.region = "{box: {min: [0, 0], max: [1, 1]}}";
  parts.more_bodies = "  wall: {material: soil, region: {box: {min: [0.5, 0], max: [2, 1]}}}\n";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(
      err, where(model, "  wall:", "bodies.wall.region") + "bodies 'wall' and 'soil' overlap"));
  EXPECT_TRUE(Contains(err, "(at x = ["));
}

TEST_F(CliErrors, PointSetSelectsNoPoint) {
  write("mesh.msh", msh_text(two_quads()));
  ModelParts parts;
  // 4 points per cell sit at y = 0.25 and 0.75: none in the top 5 %.
  parts.point_sets =
      "point_sets:\n  crest: {body: soil, region: {box: {min: [0, 0.95], max: [2, 1]}}}\n";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, where(model, "  crest:", "point_sets.crest") +
                                "point set 'crest' holds no material point"));
}

TEST_F(CliErrors, FixityOnABoundaryTheMeshLacks) {
  write("mesh.msh", msh_text(two_quads()));
  ModelParts parts;
  parts.fixities =
      "      - {boundary: bottom, fix: all}\n"
      "      - {boundary: right, fix: normal}\n";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, where(model, "boundary: right", "phases[0].fixities[1]") +
                                "the mesh has no boundary 'right'"));
  EXPECT_TRUE(Contains(err, "its boundaries are: bottom, left, top"));
}

TEST_F(CliErrors, PointsPerCellNotAvailableForTheImportedCellType) {
  write("mesh.msh", msh_text(two_quads()));
  ModelParts parts;
  parts.body_extra = "    points_per_cell: 3\n";  // accepted by the reader (triangles), not quad4
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, "model.yaml:"));
  EXPECT_TRUE(Contains(err, ": bodies.soil.points_per_cell: "));
  EXPECT_TRUE(Contains(err, "3 points per cell is not available for quad4"));
}

TEST_F(CliErrors, PointsPerCellErrorGivesItsLineAndTheAllowedCounts) {
  write("mesh.msh", msh_text(two_quads()));
  ModelParts parts;
  parts.body_extra = "    points_per_cell: 3\n";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, where(model, "points_per_cell: 3", "bodies.soil.points_per_cell")));
  EXPECT_TRUE(Contains(err, "1, 4, 9, 16"));
}

TEST_F(CliErrors, AxisymmetricMeshWithNegativeRadius) {
  Msh mesh = two_quads();
  for (auto& node : mesh.nodes) node[0] -= 1.0;  // [-1, 1] x [0, 1]
  write("mesh.msh", msh_text(mesh));
  ModelParts parts;
  parts.kinematics = "axisymmetric";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, where(model, "mesh: {file", "mesh") +
                                "axisymmetric meshes must lie in x >= 0 (x is the radius)"));
  EXPECT_TRUE(Contains(err, "is at x = -1"));
}

// GIMP weights are tensor products along grid lines (docs/theory.md §9): an imported mesh that
// is a rectilinear grid is accepted, an L-shaped one (not a complete grid) or triangles are not.
TEST_F(CliErrors, GimpNeedsARectilinearGrid) {
  ModelParts parts;
  parts.numerics = "numerics:\n  interpolation: gimp\n";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  write("mesh.msh", msh_text(two_quads()));
  const auto check = geompm({"check", "model.yaml"});
  EXPECT_TRUE(check.exited && check.exit_code == 0) << describe(check);

  write("mesh.msh", msh_text(l_shape()));
  std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, where(model, "interpolation: gimp", "numerics.interpolation") +
                                "gimp needs a rectilinear grid"))
      << err;
  EXPECT_TRUE(Contains(err, "8 nodes on 3 distinct x and 3 distinct y coordinates")) << err;

  Msh triangles = two_quads();
  triangles.gmsh_type = 2;
  triangles.cells = {{1, 2, 5}, {1, 5, 4}, {2, 3, 6}, {2, 6, 5}};
  write("mesh.msh", msh_text(triangles));
  err = expect_input_error();
  EXPECT_TRUE(Contains(err, "the mesh has tri3 cells")) << err;
}

TEST_F(CliErrors, MaterialPointsNeedLinearCells) {
  // Tri6's negative corner shape functions give nodes negative mass: a body seeding points in a
  // tri6 cell (an MPM cell) is refused when the model is built, before any step runs.
  ModelParts parts;
  parts.mesh =
      "mesh:\n  generate: {cell: tri6, origin: [0, 0], x: [{length: 2, cells: 2}], "
      "y: [{length: 1, cells: 1}]}";
  parts.region = "{box: {min: [0, 0], max: [2, 1]}}";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, "material points need linear cells")) << err;
  EXPECT_TRUE(Contains(err, "tri6 cell 0")) << err;
}

TEST_F(CliErrors, HistoryOnABoundaryTheMeshLacks) {
  write("mesh.msh", msh_text(two_quads()));
  ModelParts parts;
  parts.output =
      "output:\n"
      "  history:\n"
      "    - {quantity: reaction, boundary: bottom, component: y}\n"
      "    - {quantity: reaction, boundary: right, component: x}\n";
  const std::string model = model_text(parts);
  write("model.yaml", model);
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, where(model, "boundary: right", "output.history[1]") +
                                "the mesh has no boundary 'right'"));
}

TEST_F(CliErrors, HistoryBoundaryErrorListsTheBoundaries) {
  write("mesh.msh", msh_text(two_quads()));
  ModelParts parts;
  parts.output =
      "output:\n"
      "  history:\n"
      "    - {quantity: reaction, boundary: right, component: x}\n";
  write("model.yaml", model_text(parts));
  const std::string err = expect_input_error();
  EXPECT_TRUE(Contains(err, "its boundaries are: bottom, left, top"));
}

// Errors in the mesh file name the mesh file; they should also say which model (and which key)
// asked for that mesh, as every other model error does.
TEST_F(CliErrors, MeshFileErrorsNameTheModelFile) {
  Msh inverted = two_quads();
  inverted.cells[0] = {1, 4, 5, 2};
  write("inverted.msh", msh_text(inverted));
  write("garbage.msh", "not a mesh\n");
  for (const std::string mesh : {"inverted.msh", "garbage.msh"}) {
    SCOPED_TRACE(mesh);
    ModelParts parts;
    parts.mesh = "mesh: {file: " + mesh + "}";
    const std::string model = model_text(parts);
    write("model.yaml", model);
    const std::string err = expect_input_error();
    EXPECT_TRUE(Contains(err, where(model, "mesh: {file", "mesh.file")));
  }
}

TEST_F(CliErrors, MissingModelFile) {
  for (const auto& args : std::vector<std::vector<std::string>>{
           {"check", "nowhere.yaml"}, {"run", "-q", "-o", "out", "nowhere.yaml"}}) {
    const auto r = geompm(args);
    EXPECT_TRUE(r.exited && r.exit_code == 2) << describe(r);
    EXPECT_TRUE(Contains(r.err, "nowhere.yaml: the model file does not exist"));
  }
  EXPECT_FALSE(fs::exists(work() / "out"));
  EXPECT_TRUE(unexpected_files().empty());
}

TEST_F(CliErrors, UnknownCommandLineOption) {
  write("mesh.msh", msh_text(two_quads()));
  write("model.yaml", model_text({}));
  const auto r = geompm({"run", "--frobnicate", "-o", "out", "model.yaml"});
  EXPECT_TRUE(r.exited && r.exit_code == 1) << describe(r);
  EXPECT_TRUE(Contains(r.err, "--frobnicate"));
  EXPECT_TRUE(Contains(r.err, "--help"));
  EXPECT_FALSE(fs::exists(work() / "out"));
}

TEST_F(CliErrors, OtherBadCommandLines) {
  write("mesh.msh", msh_text(two_quads()));
  write("model.yaml", model_text({}));
  const auto zero_threads = geompm({"run", "-t", "0", "-o", "out", "model.yaml"});
  EXPECT_TRUE(zero_threads.exited && zero_threads.exit_code == 1) << describe(zero_threads);
  EXPECT_TRUE(Contains(zero_threads.err, "--threads"));
  EXPECT_FALSE(Contains(zero_threads.err, "179769313486"));
  const auto no_model = geompm({"run", "-o", "out"});
  EXPECT_TRUE(no_model.exited && no_model.exit_code == 1) << describe(no_model);
  EXPECT_TRUE(Contains(no_model.err, "model"));
  const auto unknown = geompm({"frobnicate", "model.yaml"});
  EXPECT_TRUE(unknown.exited && unknown.exit_code == 1) << describe(unknown);
  EXPECT_TRUE(Contains(unknown.err, "frobnicate"));
  EXPECT_FALSE(fs::exists(work() / "out"));
}

TEST_F(CliErrors, PlotOfAMissingColumn) {
  write("history.csv", "time,step,top_uy\n0,0,0\n0.5,1,-0.05\n1,2,-0.1\n");
  const auto bad = geompm({"plot", "history.csv", "--x", "time", "--y", "top_ux", "-o", "p.png"});
  EXPECT_TRUE(bad.exited && bad.exit_code == 2) << describe(bad);
  EXPECT_TRUE(Contains(bad.err, "history.csv: no column 'top_ux'"));
  EXPECT_TRUE(Contains(bad.err, "the columns are: time, step, top_uy"));
  EXPECT_FALSE(fs::exists(work() / "p.png")) << "a failed plot wrote its PNG";
  EXPECT_TRUE(unexpected_files().empty());

  // The same request with an existing column draws the plot: the failure above is the column's.
  const auto good = geompm({"plot", "history.csv", "--x", "time", "--y", "top_uy", "-o", "p.png"});
  EXPECT_TRUE(good.exited && good.exit_code == 0) << describe(good);
  const std::string png = read_text(work() / "p.png");
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

}  // namespace
