// The .vtu files are read back by an independent reader (meshio, through
// tests/tools/read_vtu.py) and every value is compared with what was written: positions, cell
// types and connectivity, and each field with its type, component count and component order.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <regex>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "geompm/io/vtk_writer.hpp"
#include "read_vtu.hpp"

namespace geompm {
namespace {

namespace fs = std::filesystem;
using testing::check_layout;
using testing::read_with_meshio;
using testing::ReadArray;
using testing::ReadVtu;
using testing::run_reader;

/// A fresh directory per test, removed afterwards.
class TempDir {
 public:
  TempDir() {
    const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
    path_ = fs::temp_directory_path() / (std::string("geompm_") + info->test_suite_name() + "_" +
                                         info->name() + "_" + std::to_string(::getpid()));
    fs::remove_all(path_);
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ignored;
    fs::remove_all(path_, ignored);
  }
  const fs::path& path() const { return path_; }
  std::vector<std::string> entries() const {
    std::vector<std::string> names;
    for (const auto& e : fs::directory_iterator(path_)) names.push_back(e.path().filename());
    std::sort(names.begin(), names.end());
    return names;
  }

 private:
  fs::path path_;
};

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

Mat3 symmetric(double xx, double yy, double zz, double xy, double yz, double xz) {
  Mat3 t;
  t << xx, xy, xz, xy, yy, yz, xz, yz, zz;
  return t;
}

// --- comparisons: exact, because the file and the reader's text both carry every bit --------

void expect_scalars(const ReadArray& read, const std::vector<double>& written) {
  EXPECT_EQ(read.dtype, "float64");
  EXPECT_EQ(read.components, 1);
  ASSERT_EQ(read.rows.size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i) {
    ASSERT_EQ(read.rows[i].size(), 1u);
    EXPECT_EQ(read.rows[i][0], written[i]) << "value " << i;
  }
}

void expect_vectors(const ReadArray& read, const std::vector<Vec3>& written) {
  EXPECT_EQ(read.dtype, "float64");
  EXPECT_EQ(read.components, 3);
  ASSERT_EQ(read.rows.size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i) {
    ASSERT_EQ(read.rows[i].size(), 3u);
    for (int k = 0; k < 3; ++k) EXPECT_EQ(read.rows[i][k], written[i][k]) << i << "," << k;
  }
}

// ParaView's order of a symmetric tensor: xx, yy, zz, xy, yz, xz.
void expect_tensors(const ReadArray& read, const std::vector<Mat3>& written) {
  EXPECT_EQ(read.dtype, "float64");
  EXPECT_EQ(read.components, 6);
  ASSERT_EQ(read.rows.size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i) {
    const Mat3& t = written[i];
    const std::vector<double> expected = {t(0, 0), t(1, 1), t(2, 2), t(0, 1), t(1, 2), t(0, 2)};
    EXPECT_EQ(read.rows[i], expected) << "tensor " << i;
  }
}

void expect_integers(const ReadArray& read, const std::vector<Index>& written) {
  EXPECT_EQ(read.dtype, "int32");
  EXPECT_EQ(read.components, 1);
  ASSERT_EQ(read.rows.size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i)
    EXPECT_EQ(read.rows[i], std::vector<double>{static_cast<double>(written[i])}) << i;
}

void expect_points(const ReadVtu& read, const std::vector<Vec3>& written) {
  ASSERT_EQ(read.points.size(), written.size());
  for (std::size_t i = 0; i < written.size(); ++i)
    EXPECT_EQ(read.points[i], (std::vector<double>{written[i].x(), written[i].y(), written[i].z()}))
        << "point " << i;
}

void expect_cells(const ReadVtu& read, const std::string& meshio_type, const Mesh& mesh) {
  ASSERT_EQ(read.cells.size(), 1u);
  ASSERT_TRUE(read.cells.count(meshio_type)) << "no " << meshio_type << " cells";
  const auto& cells = read.cells.at(meshio_type);
  ASSERT_EQ(static_cast<Index>(cells.size()), mesh.num_cells());
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell_nodes(c);
    EXPECT_EQ(cells[c], std::vector<double>(nodes.begin(), nodes.end())) << "cell " << c;
  }
}

// --- points ------------------------------------------------------------------------------------

TEST(VtkWriter, PointsRoundTripThroughAnIndependentReader) {
  TempDir dir;
  const std::vector<Vec3> positions = {
      {0.1, 1.0 / 3.0, 0.0}, {-2.5e-7, 1e5 + 0.3, 7.0}, {3.0, -4.0, 1e-300}, {0.0, 0.0, -0.5}};
  FieldSet fields;
  fields.scalars.push_back({"pressure", {1.5, -2.0 / 3.0, 0.0, 123456.789}});
  fields.vectors.push_back({"velocity", {{1, 2, 3}, {-4, 5.5, 6}, {0, 0, 1e-9}, {7, 8, 9}}});
  fields.tensors.push_back(
      {"stress",
       {symmetric(11, 22, 33, 12, 23, 13), symmetric(-1, -2, -3, -4, -5, -6),
        symmetric(0.1, 0.2, 0.3, 0.4, 0.5, 0.6), symmetric(1e3, 2e3, 3e3, 4e3, 5e3, 6e3)}});
  fields.integers.push_back({"body", {0, 1, 2, -7}});
  const fs::path file = dir.path() / "points.vtu";
  write_vtu_points(file, positions, fields);

  const ReadVtu read = read_with_meshio(file);
  expect_points(read, positions);
  ASSERT_TRUE(read.cells.count("vertex"));
  const auto& vertices = read.cells.at("vertex");
  ASSERT_EQ(vertices.size(), positions.size());
  for (std::size_t i = 0; i < positions.size(); ++i)
    EXPECT_EQ(vertices[i], std::vector<double>{static_cast<double>(i)});
  ASSERT_EQ(read.point_data.size(), 4u);
  expect_scalars(read.point_data.at("pressure"), fields.scalars[0].second);
  expect_vectors(read.point_data.at("velocity"), fields.vectors[0].second);
  expect_tensors(read.point_data.at("stress"), fields.tensors[0].second);
  expect_integers(read.point_data.at("body"), fields.integers[0].second);
}

TEST(VtkWriter, HeaderDeclaresAppendedRawDataWithUInt64SizesLittleEndian) {
  TempDir dir;
  const fs::path file = dir.path() / "p.vtu";
  FieldSet fields;
  fields.scalars.push_back({"a", {1.0, 2.0}});
  write_vtu_points(file, {{0, 0, 0}, {1, 1, 1}}, fields);
  const std::string text = read_text(file);
  const std::size_t appended = text.find("<AppendedData encoding=\"raw\">");
  ASSERT_NE(appended, std::string::npos);
  const std::string header = text.substr(0, appended);
  EXPECT_NE(header.find("type=\"UnstructuredGrid\""), std::string::npos);
  EXPECT_NE(header.find("header_type=\"UInt64\""), std::string::npos);
  EXPECT_NE(header.find("byte_order=\"LittleEndian\""), std::string::npos);
  EXPECT_EQ(header.find("format=\"ascii\""), std::string::npos);
  EXPECT_EQ(header.find("format=\"binary\""), std::string::npos);
  // The scalar "a": at its offset, a UInt64 byte count of 16, then 1.0 and 2.0.
  std::smatch match;
  const std::regex tag(
      R"re(<DataArray type="Float64" Name="a" NumberOfComponents="1" format="appended" offset="(\d+)"/>)re");
  ASSERT_TRUE(std::regex_search(header, match, tag)) << header;
  const std::size_t offset = std::stoul(match[1].str());
  const std::size_t underscore = text.find('_', appended);
  ASSERT_NE(underscore, std::string::npos);
  ASSERT_LT(underscore + 1 + offset + 24, text.size());
  const unsigned char* bytes =
      reinterpret_cast<const unsigned char*>(text.data()) + underscore + 1 + offset;
  std::uint64_t size = 0;
  for (int i = 7; i >= 0; --i) size = (size << 8) | bytes[i];  // little-endian
  EXPECT_EQ(size, 16u);
  double values[2];
  std::memcpy(values, bytes + 8, sizeof values);  // the test machine is little-endian too
  EXPECT_EQ(values[0], 1.0);
  EXPECT_EQ(values[1], 2.0);
}

TEST(VtkWriter, ZeroPointsMakeAValidEmptyFile) {
  TempDir dir;
  const fs::path file = dir.path() / "empty.vtu";
  FieldSet fields;
  fields.scalars.push_back({"pressure", {}});
  fields.tensors.push_back({"stress", {}});
  write_vtu_points(file, {}, fields);
  const std::string text = read_text(file);
  EXPECT_NE(text.find("NumberOfPoints=\"0\" NumberOfCells=\"0\""), std::string::npos);
  // meshio 5.0 cannot read a file without cells (it indexes the first cell type), so the
  // layout is checked by the script's own parser: 4 arrays (Points, connectivity, offsets,
  // types) and the two fields, all empty blocks.
  EXPECT_EQ(check_layout(file), "LAYOUT 0 0 6");
}

TEST(VtkWriter, LayoutCheckRejectsACorruptedFile) {
  TempDir dir;
  const fs::path file = dir.path() / "p.vtu";
  FieldSet fields;
  fields.scalars.push_back({"a", {1.0, 2.0}});
  write_vtu_points(file, {{0, 0, 0}, {1, 1, 1}}, fields);
  EXPECT_EQ(check_layout(file), "LAYOUT 2 2 5");
  // One byte fewer in the last block: the checker (and so every round-trip test) must notice.
  std::string text = read_text(file);
  text.erase(text.rfind("\n  </AppendedData>") - 1, 1);
  std::ofstream(file, std::ios::binary | std::ios::trunc) << text;
  EXPECT_THROW(check_layout(file), std::runtime_error);
}

TEST(VtkWriter, FieldOfWrongSizeIsRefusedWithItsNameAndNoFileIsLeft) {
  TempDir dir;
  const fs::path file = dir.path() / "bad.vtu";
  FieldSet fields;
  fields.scalars.push_back({"pressure", {1.0, 2.0}});
  fields.vectors.push_back({"velocity", {{1, 2, 3}}});  // 1 value for 2 points
  try {
    write_vtu_points(file, {{0, 0, 0}, {1, 0, 0}}, fields);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("velocity"), std::string::npos) << e.what();
  }
  FieldSet integers;
  integers.integers.push_back({"body", {1, 2, 3}});
  EXPECT_THROW(write_vtu_points(file, {{0, 0, 0}, {1, 0, 0}}, integers), std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

// --- meshes ------------------------------------------------------------------------------------

/// Two unit squares side by side: nodes 0 1 2 along y = 0, 3 4 5 along y = 1.
Mesh two_quads() {
  Mesh mesh;
  mesh.cell_type = CellType::Quad4;
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 1, 0}};
  mesh.connectivity = {0, 1, 4, 3, 1, 2, 5, 4};
  return mesh;
}

TEST(VtkWriter, Quad4MeshRoundTripWithNodeAndCellData) {
  TempDir dir;
  const Mesh mesh = two_quads();
  // The written positions are the deformed ones passed in, not mesh.nodes.
  std::vector<Vec3> deformed = mesh.nodes;
  for (std::size_t i = 0; i < deformed.size(); ++i) deformed[i] += Vec3(0.01 * i, -0.02 * i, 0);
  FieldSet node_fields, cell_fields;
  node_fields.scalars.push_back({"mass", {1, 2, 3, 4, 5, 6.25}});
  node_fields.vectors.push_back(
      {"displacement", {{0, 0, 0}, {0.1, 0, 0}, {0.2, 0, 0}, {0, -0.1, 0}, {1, 2, 3}, {4, 5, 6}}});
  node_fields.integers.push_back({"active", {1, 1, 0, 1, 0, 1}});
  cell_fields.scalars.push_back({"volume_ratio", {0.25, 0.75}});
  cell_fields.vectors.push_back({"centroid_shift", {{1, -1, 0}, {-2, 2, 0.5}}});
  cell_fields.tensors.push_back(
      {"mean_stress", {symmetric(1, 2, 3, 4, 5, 6), symmetric(-10, -20, -30, 0.5, 0.25, 0.125)}});
  cell_fields.integers.push_back({"points_in_cell", {4, 0}});
  const fs::path file = dir.path() / "grid.vtu";
  write_vtu_mesh(file, mesh, deformed, node_fields, cell_fields);

  const ReadVtu read = read_with_meshio(file);
  expect_points(read, deformed);
  expect_cells(read, "quad", mesh);
  ASSERT_EQ(read.point_data.size(), 3u);
  expect_scalars(read.point_data.at("mass"), node_fields.scalars[0].second);
  expect_vectors(read.point_data.at("displacement"), node_fields.vectors[0].second);
  expect_integers(read.point_data.at("active"), node_fields.integers[0].second);
  ASSERT_EQ(read.cell_data.size(), 4u);
  expect_scalars(read.cell_data.at("volume_ratio"), cell_fields.scalars[0].second);
  expect_vectors(read.cell_data.at("centroid_shift"), cell_fields.vectors[0].second);
  expect_tensors(read.cell_data.at("mean_stress"), cell_fields.tensors[0].second);
  expect_integers(read.cell_data.at("points_in_cell"), cell_fields.integers[0].second);
}

TEST(VtkWriter, Tri6IsAQuadraticTriangleWithGeompmNodeOrder) {
  TempDir dir;
  Mesh mesh;
  mesh.cell_type = CellType::Tri6;
  // Node numbers deliberately not 0..5 in order, so a reordering would show.
  mesh.nodes = {{0.5, 0.5, 0}, {0.5, 0, 0}, {0, 0.5, 0}, {0, 1, 0}, {1, 0, 0}, {0, 0, 0}};
  mesh.connectivity = {5, 4, 3, 1, 0, 2};  // corners 0,1,2 then mid-sides 01, 12, 20
  FieldSet node_fields, cell_fields;
  node_fields.scalars.push_back({"level_set", {-1, -0.5, 0, 0.5, 1, 1.5}});
  cell_fields.tensors.push_back({"stress", {symmetric(1, 2, 3, 4, 5, 6)}});
  const fs::path file = dir.path() / "tri6.vtu";
  write_vtu_mesh(file, mesh, mesh.nodes, node_fields, cell_fields);

  const ReadVtu read = read_with_meshio(file);
  expect_points(read, mesh.nodes);
  expect_cells(read, "triangle6", mesh);
  expect_scalars(read.point_data.at("level_set"), node_fields.scalars[0].second);
  expect_tensors(read.cell_data.at("stress"), cell_fields.tensors[0].second);
}

TEST(VtkWriter, Hex8MeshRoundTrip) {
  TempDir dir;
  Mesh mesh;
  mesh.cell_type = CellType::Hex8;
  mesh.nodes = {{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0},
                {0, 0, 3}, {2, 0, 3}, {2, 1, 3}, {0, 1, 3}};
  mesh.connectivity = {0, 1, 2, 3, 4, 5, 6, 7};
  FieldSet node_fields, cell_fields;
  std::vector<Vec3> velocity;
  for (int i = 0; i < 8; ++i) velocity.push_back(Vec3(i, -i, 0.5 * i));
  node_fields.vectors.push_back({"velocity", velocity});
  cell_fields.scalars.push_back({"density", {1.9}});
  cell_fields.tensors.push_back({"stress", {symmetric(-100, -200, -300, 10, 20, 30)}});
  cell_fields.integers.push_back({"material", {3}});
  const fs::path file = dir.path() / "hex.vtu";
  write_vtu_mesh(file, mesh, mesh.nodes, node_fields, cell_fields);

  const ReadVtu read = read_with_meshio(file);
  expect_points(read, mesh.nodes);
  expect_cells(read, "hexahedron", mesh);
  expect_vectors(read.point_data.at("velocity"), velocity);
  expect_scalars(read.cell_data.at("density"), {1.9});
  expect_tensors(read.cell_data.at("stress"), cell_fields.tensors[0].second);
  expect_integers(read.cell_data.at("material"), {3});
}

TEST(VtkWriter, Tri3AndTet4HaveTheirVtkCellTypes) {
  TempDir dir;
  Mesh tri;
  tri.cell_type = CellType::Tri3;
  tri.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  tri.connectivity = {0, 1, 2, 0, 2, 3};
  write_vtu_mesh(dir.path() / "tri.vtu", tri, tri.nodes, {}, {});
  expect_cells(read_with_meshio(dir.path() / "tri.vtu"), "triangle", tri);

  Mesh tet;
  tet.cell_type = CellType::Tet4;
  tet.nodes = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {1, 1, 1}};
  tet.connectivity = {0, 1, 2, 3, 1, 2, 3, 4};
  write_vtu_mesh(dir.path() / "tet.vtu", tet, tet.nodes, {}, {});
  expect_cells(read_with_meshio(dir.path() / "tet.vtu"), "tetra", tet);
}

TEST(VtkWriter, AMixedMeshWritesEachCellWithItsOwnType) {
  // A triangle beside a quadrangle (issue 43): VTK reads each with its type and its nodes.
  TempDir dir;
  Mesh mesh;
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {2, 0, 0}, {2, 1, 0}};
  const std::vector<Index> triangle = {0, 1, 2}, quadrangle = {1, 3, 4, 2};
  mesh.add_cell(CellType::Tri3, triangle);
  mesh.add_cell(CellType::Quad4, quadrangle);
  ASSERT_TRUE(mesh.mixed());
  FieldSet cells;
  cells.scalars.push_back({"fill", {0.25, 0.75}});
  write_vtu_mesh(dir.path() / "mixed.vtu", mesh, mesh.nodes, {}, cells);
  const ReadVtu read = read_with_meshio(dir.path() / "mixed.vtu");
  ASSERT_EQ(read.cells.count("triangle"), 1u);
  ASSERT_EQ(read.cells.count("quad"), 1u);
  EXPECT_EQ(read.cells.at("triangle"), (std::vector<std::vector<double>>{{0, 1, 2}}));
  EXPECT_EQ(read.cells.at("quad"), (std::vector<std::vector<double>>{{1, 3, 4, 2}}));
  expect_scalars(read.cell_data.at("fill"), {0.25});  // meshio's first block: the triangle
}

TEST(VtkWriter, A3dMixedMeshWritesHexahedraPyramidsAndTetrahedra) {
  // A hexahedron, the pyramid on its face x = 1 and a tetrahedron on one of the pyramid's
  // triangles: VTK (meshio) reads each with its type (VTK_PYRAMID = 14) and its nodes in
  // geompm's (Gmsh's) order, which is VTK's.
  TempDir dir;
  Mesh mesh;
  mesh.nodes = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},       {0, 0, 1},
                {1, 0, 1}, {1, 1, 1}, {0, 1, 1}, {1.5, 0.5, 0.5}, {1.5, 1.5, 0.5}};
  const std::vector<Index> hexahedron = {0, 1, 2, 3, 4, 5, 6, 7}, pyramid = {1, 2, 6, 5, 8},
                           tetrahedron = {2, 9, 6, 8};
  mesh.add_cell(CellType::Hex8, hexahedron);
  mesh.add_cell(CellType::Pyramid5, pyramid);
  mesh.add_cell(CellType::Tet4, tetrahedron);
  ASSERT_TRUE(mesh.mixed());
  FieldSet cells;
  cells.scalars.push_back({"fill", {0.25, 0.5, 0.75}});
  write_vtu_mesh(dir.path() / "mixed3d.vtu", mesh, mesh.nodes, {}, cells);
  const ReadVtu read = read_with_meshio(dir.path() / "mixed3d.vtu");
  ASSERT_EQ(read.cells.count("hexahedron"), 1u);
  ASSERT_EQ(read.cells.count("pyramid"), 1u);
  ASSERT_EQ(read.cells.count("tetra"), 1u);
  EXPECT_EQ(read.cells.at("hexahedron"),
            (std::vector<std::vector<double>>{{0, 1, 2, 3, 4, 5, 6, 7}}));
  EXPECT_EQ(read.cells.at("pyramid"), (std::vector<std::vector<double>>{{1, 2, 6, 5, 8}}));
  EXPECT_EQ(read.cells.at("tetra"), (std::vector<std::vector<double>>{{2, 9, 6, 8}}));
  expect_points(read, mesh.nodes);
  expect_scalars(read.cell_data.at("fill"), {0.25});  // meshio's first block: the hexahedron
}

TEST(VtkWriter, MeshFieldsOfWrongSizeAreRefusedWithTheirName) {
  TempDir dir;
  const Mesh mesh = two_quads();
  FieldSet node_fields, cell_fields;
  node_fields.scalars.push_back({"mass", {1, 2, 3}});  // 3 values for 6 nodes
  try {
    write_vtu_mesh(dir.path() / "g.vtu", mesh, mesh.nodes, node_fields, {});
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mass"), std::string::npos) << e.what();
  }
  cell_fields.tensors.push_back({"stress", {Mat3::Zero()}});  // 1 value for 2 cells
  try {
    write_vtu_mesh(dir.path() / "g.vtu", mesh, mesh.nodes, {}, cell_fields);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("stress"), std::string::npos) << e.what();
  }
  // Fewer positions than the cells use.
  const std::vector<Vec3> too_few(mesh.nodes.begin(), mesh.nodes.begin() + 4);
  EXPECT_THROW(write_vtu_mesh(dir.path() / "g.vtu", mesh, too_few, {}, {}), std::invalid_argument);
  EXPECT_TRUE(dir.entries().empty());
}

// --- atomic writes -----------------------------------------------------------------------------

TEST(VtkWriter, AtomicWriteReplacesTheFileAndLeavesNoTemporaryBehind) {
  TempDir dir;
  const fs::path file = dir.path() / "out.txt";
  write_file_atomically(file, "first version, longer than the second");
  write_file_atomically(file, "second");
  EXPECT_EQ(read_text(file), "second");
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"out.txt"});

  // Binary content (with NUL bytes) survives unchanged.
  const std::string binary("a\0b\n\r\xff", 6);
  write_file_atomically(file, binary);
  EXPECT_EQ(read_text(file), binary);

  write_vtu_points(dir.path() / "points.vtu", {{0, 0, 0}}, {});
  const Mesh mesh = two_quads();
  write_vtu_mesh(dir.path() / "grid.vtu", mesh, mesh.nodes, {}, {});
  EXPECT_EQ(dir.entries(), (std::vector<std::string>{"grid.vtu", "out.txt", "points.vtu"}));
}

TEST(VtkWriter, AtomicWriteCreatesMissingDirectories) {
  TempDir dir;
  const fs::path file = dir.path() / "vtk" / "points" / "p.vtu";
  write_file_atomically(file, "x");
  EXPECT_EQ(read_text(file), "x");
  EXPECT_EQ(std::distance(fs::directory_iterator(file.parent_path()), fs::directory_iterator()), 1);
}

// --- pvd ---------------------------------------------------------------------------------------

/// (timestep, file) of every DataSet of a .pvd, in order.
std::vector<std::pair<double, std::string>> datasets(const fs::path& pvd) {
  const std::string text = read_text(pvd);
  std::vector<std::pair<double, std::string>> found;
  const std::regex dataset(R"re(<DataSet\s+timestep="([^"]*)"[^>]*\sfile="([^"]*)"\s*/>)re");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), dataset);
       it != std::sregex_iterator(); ++it)
    found.emplace_back(std::stod((*it)[1].str()), (*it)[2].str());
  return found;
}

TEST(PvdSeries, EveryAddRewritesTheCollectionWithAllDatasetsAndExactTimes) {
  TempDir dir;
  PvdSeries series(dir.path() / "points.pvd");
  EXPECT_EQ(series.path(), dir.path() / "points.pvd");
  const std::vector<std::pair<double, std::string>> expected = {
      {0.0, "points/points_000000.vtu"},
      {0.1, "points/points_000001.vtu"},
      {1.0 / 3.0, "points/points_000002.vtu"}};

  series.add(expected[0].first, expected[0].second);
  EXPECT_EQ(datasets(series.path()),
            (std::vector<std::pair<double, std::string>>(expected.begin(), expected.begin() + 1)));
  series.add(expected[1].first, expected[1].second);
  series.add(expected[2].first, expected[2].second);
  // Exact equality: the times carry full double precision (1/3 would not survive 6 digits).
  EXPECT_EQ(datasets(series.path()), expected);

  const std::string text = read_text(series.path());
  EXPECT_NE(text.find("<VTKFile type=\"Collection\""), std::string::npos);
  EXPECT_NE(text.find("<Collection>"), std::string::npos);
  EXPECT_NE(text.find("</Collection>"), std::string::npos);
  EXPECT_EQ(dir.entries(), std::vector<std::string>{"points.pvd"});
}

TEST(PvdSeries, FileNamesAreXmlEscaped) {
  TempDir dir;
  PvdSeries series(dir.path() / "s.pvd");
  series.add(2.5, "a&b<c>.vtu");
  const std::string text = read_text(series.path());
  EXPECT_NE(text.find("file=\"a&amp;b&lt;c&gt;.vtu\""), std::string::npos) << text;
}

}  // namespace
}  // namespace geompm
