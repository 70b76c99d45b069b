// Gmsh: generation of unstructured meshes, import, and the errors a user sees for bad files.
#include <gmsh.h>
#include <gtest/gtest.h>

#include <Eigen/Geometry>

#include <clocale>
#include <fstream>
#include <map>
#include <stdexcept>
#include <string>

#include "geompm/core/error.hpp"
#include "geompm/mesh/cell_faces.hpp"
#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/gmsh_generate.hpp"
#include "geompm/mesh/gmsh_import.hpp"
#include "geompm/mesh/gmsh_session.hpp"
#include "mesh_test_support.hpp"

namespace geompm {
namespace {

using testing::TemporaryDirectory;
using testing::total_measure;

void expect_groups_on_their_sides(const Mesh& mesh, const Vec3& lower, const Vec3& upper,
                                  bool has_all = true) {
  struct Side {
    const char* name;
    int axis;
    double at;
  };
  std::vector<Side> sides = {{"left", 0, lower[0]}, {"right", 0, upper[0]}};
  if (mesh.dim() == 3)
    sides.insert(sides.end(), {{"front", 1, lower[1]},
                               {"back", 1, upper[1]},
                               {"bottom", 2, lower[2]},
                               {"top", 2, upper[2]}});
  else
    sides.insert(sides.end(), {{"bottom", 1, lower[1]}, {"top", 1, upper[1]}});
  for (const Side& side : sides) {
    ASSERT_TRUE(mesh.node_groups.count(side.name)) << side.name;
    const std::vector<Index>& ids = mesh.node_groups.at(side.name);
    EXPECT_TRUE(std::is_sorted(ids.begin(), ids.end()));
    std::size_t expected = 0;  // every node on that side, and no other
    for (const Vec3& x : mesh.nodes) expected += std::abs(x[side.axis] - side.at) < 1e-12;
    EXPECT_EQ(ids.size(), expected) << side.name;
    for (Index n : ids) EXPECT_NEAR(mesh.nodes[n][side.axis], side.at, 1e-12) << side.name;
  }
  if (!has_all) return;
  ASSERT_TRUE(mesh.cell_groups.count("all"));
  EXPECT_EQ(static_cast<Index>(mesh.cell_groups.at("all").size()), mesh.num_cells());
}

TEST(GmshTest, RectangleRoundTripForEveryTwoDimensionalType) {
  TemporaryDirectory directory;
  const Vec3 origin(-1.0, 0.5, 0.0), size(3.0, 2.0, 0.0);
  for (CellType type : {CellType::Tri3, CellType::Quad4, CellType::Tri6}) {
    SCOPED_TRACE(to_string(type));
    const auto file = directory.path() / (std::string(to_string(type)) + ".msh");
    write_gmsh_rectangle(file, origin, size, 0.25, type);
    std::ifstream text(file);
    std::string first, version;
    text >> first >> version;
    EXPECT_EQ(first, "$MeshFormat");
    EXPECT_EQ(version, "4.1");

    const Mesh mesh = read_gmsh_mesh(file.string(), 2);
    EXPECT_EQ(mesh.cell_type, type);
    EXPECT_GT(mesh.num_cells(), 50);
    EXPECT_NEAR(total_measure(mesh), 6.0, 1e-10);
    // int x dA over [-1, 2] x [0.5, 2.5]: (4 - 1) / 2 * 2.
    EXPECT_NEAR(total_measure(mesh, true), 3.0, 1e-10);
    EXPECT_NO_THROW(validate_mesh(mesh, file.string()));
    expect_groups_on_their_sides(mesh, origin, origin + size);
    // Compact numbering: every node is used by a cell.
    std::vector<char> used(mesh.nodes.size(), 0);
    for (Index n : mesh.connectivity) used[n] = 1;
    EXPECT_EQ(std::count(used.begin(), used.end(), 0), 0);
  }
}

TEST(GmshTest, RefinementBoxMakesSmallerCellsInside) {
  for (CellType type : {CellType::Tri3, CellType::Quad4}) {
    const Mesh& mesh = testing::gmsh_mesh(type);  // h = 0.15 outside, 0.05 in the box
    double inside = 0.0, outside = 0.0;
    int count_inside = 0, count_outside = 0;
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const Vec3 centre = map_to_physical(mesh, c, Vec3(0.3, 0.3, 0.0));
      const bool in_box =
          centre[0] > 0.55 && centre[0] < 0.95 && centre[1] > 0.25 && centre[1] < 0.55;
      const bool far = centre[0] > 1.5;
      if (in_box) inside += cell_measure(mesh, c), ++count_inside;
      if (far) outside += cell_measure(mesh, c), ++count_outside;
    }
    ASSERT_GT(count_inside, 0);
    ASSERT_GT(count_outside, 0);
    EXPECT_LT(inside / count_inside, 0.3 * outside / count_outside) << to_string(type);
    EXPECT_NEAR(total_measure(mesh), 2.0, 1e-10);
  }
}

TEST(GmshTest, BoxRoundTripWithTetrahedra) {
  TemporaryDirectory directory;
  const Vec3 origin(1.0, -1.0, -2.0), size(2.0, 1.0, 1.5);
  const auto file = directory.path() / "box.msh";
  write_gmsh_box(file, origin, size, 0.3);
  const Mesh mesh = read_gmsh_mesh(file.string(), 3);
  EXPECT_EQ(mesh.cell_type, CellType::Tet4);
  EXPECT_GT(mesh.num_cells(), 100);
  EXPECT_NEAR(total_measure(mesh), 3.0, 1e-10);
  expect_groups_on_their_sides(mesh, origin, origin + size);
  // Read as 2D the file has triangles (the boundary faces), which geompm takes as the mesh
  // only when asked for 2D; they are not in the plane z = 0, so that is refused.
  EXPECT_THROW(read_gmsh_mesh(file.string(), 2), InputError);
}

TEST(GmshTest, GeneratorsRejectBadArguments) {
  TemporaryDirectory directory;
  const auto file = directory.path() / "bad.msh";
  EXPECT_THROW(write_gmsh_rectangle(file, Vec3::Zero(), Vec3(1, 0, 0), 0.1, CellType::Tri3),
               std::invalid_argument);
  EXPECT_THROW(write_gmsh_rectangle(file, Vec3::Zero(), Vec3(1, 1, 0), 0.0, CellType::Tri3),
               std::invalid_argument);
  EXPECT_THROW(write_gmsh_rectangle(file, Vec3::Zero(), Vec3(1, 1, 0), 0.1, CellType::Hex8),
               std::invalid_argument);
  EXPECT_THROW(write_gmsh_rectangle(file, Vec3::Zero(), Vec3(1, 1, 0), 0.1, CellType::Tri3,
                                    RefineBox{Vec3::Zero(), Vec3::Ones()}, 0.0),
               std::invalid_argument);
  EXPECT_THROW(write_gmsh_box(file, Vec3::Zero(), Vec3(1, 1, 1), 0.1, CellType::Hex8),
               std::invalid_argument);
  EXPECT_THROW(write_gmsh_box(file, Vec3::Zero(), Vec3(1, 1, -1), 0.1), std::invalid_argument);
  EXPECT_FALSE(std::filesystem::exists(file));
}

// ---- Import errors: hand-written files in Gmsh format 4.1 ASCII. ----

std::string write_file(const TemporaryDirectory& directory, const std::string& name,
                       const std::string& text) {
  const auto path = directory.path() / name;
  std::ofstream(path) << text;
  return path.string();
}

/// The message of the InputError thrown by read_gmsh_mesh; fails the test if none is thrown.
std::string import_error(const std::string& path, int dimension) {
  try {
    read_gmsh_mesh(path, dimension);
  } catch (const InputError& error) {
    const std::string message = error.what();
    EXPECT_NE(message.find(path), std::string::npos) << "the message names the file: " << message;
    return message;
  } catch (const std::exception& error) {
    ADD_FAILURE() << "expected an InputError, got: " << error.what();
    return "";
  }
  ADD_FAILURE() << "read_gmsh_mesh accepted " << path;
  return "";
}

/// A unit square as two triangles (nodes 1-4) with the elements given, one entity block.
std::string square_file(const std::string& z, const std::string& element_block) {
  return "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
         "$Entities\n0 0 1 0\n1 0 0 0 1 1 0 1 7 0\n$EndEntities\n"
         "$Nodes\n1 4 1 4\n2 1 0 4\n1\n2\n3\n4\n"
         "0 0 0\n1 0 0\n1 1 " +
         z + "\n0 1 0\n$EndNodes\n" + element_block;
}

const std::string two_triangles = "$Elements\n1 2 1 2\n2 1 2 2\n1 1 2 3\n2 1 3 4\n$EndElements\n";

TEST(GmshImportTest, HandWrittenFileReadsWithUnnamedGroup) {
  TemporaryDirectory directory;
  const std::string path = write_file(directory, "good.msh", square_file("0", two_triangles));
  const Mesh mesh = read_gmsh_mesh(path, 2);
  EXPECT_EQ(mesh.cell_type, CellType::Tri3);
  EXPECT_EQ(mesh.num_nodes(), 4);
  EXPECT_EQ(mesh.num_cells(), 2);
  EXPECT_EQ(mesh.connectivity, (std::vector<Index>{0, 1, 2, 0, 2, 3}));  // tags 1..4 -> 0..3
  ASSERT_TRUE(mesh.cell_groups.count("group_7"));
  EXPECT_EQ(mesh.cell_groups.at("group_7"), (std::vector<Index>{0, 1}));
}

TEST(GmshImportTest, MissingFile) {
  TemporaryDirectory directory;
  const std::string message = import_error((directory.path() / "none.msh").string(), 2);
  EXPECT_NE(message.find("not found"), std::string::npos) << message;
}

TEST(GmshImportTest, FileThatIsNotAMesh) {
  TemporaryDirectory directory;
  const std::string path = write_file(directory, "text.msh", "hello world\nthis is not a mesh\n");
  EXPECT_FALSE(import_error(path, 2).empty());
  // A well-formed mesh file that holds no cells.
  const std::string empty =
      write_file(directory, "empty.msh", "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n");
  const std::string message = import_error(empty, 2);
  EXPECT_NE(message.find("no 2D cells"), std::string::npos) << message;
}

TEST(GmshImportTest, InvertedCellIsNamedWithItsNodes) {
  TemporaryDirectory directory;
  // The second triangle runs 1-4-3: clockwise.
  const std::string path =
      write_file(directory, "inverted.msh",
                 square_file("0", "$Elements\n1 2 1 2\n2 1 2 2\n1 1 2 3\n2 1 4 3\n$EndElements\n"));
  const std::string message = import_error(path, 2);
  EXPECT_NE(message.find("cell 1 "), std::string::npos) << message;
  EXPECT_NE(message.find("(0, 1)"), std::string::npos) << message;
  EXPECT_NE(message.find("inverted"), std::string::npos) << message;
}

TEST(GmshImportTest, TwoDimensionalMeshOutOfPlane) {
  TemporaryDirectory directory;
  const std::string path = write_file(directory, "tilted.msh", square_file("0.25", two_triangles));
  const std::string message = import_error(path, 2);
  EXPECT_NE(message.find("z = 0.25"), std::string::npos) << message;
  EXPECT_NE(message.find("Gmsh node 3 "), std::string::npos) << message;
}

TEST(GmshImportTest, MixedTrianglesAndQuadrilaterals) {
  TemporaryDirectory directory;
  // Nodes 1-4 (square) plus 5-6: a quadrangle 2-5-6-3 next to triangle 1-2-3 (node 4 unused).
  const std::string path =
      write_file(directory, "mixed.msh",
                 "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                 "$Nodes\n1 6 1 6\n2 1 0 6\n1\n2\n3\n4\n5\n6\n"
                 "0 0 0\n1 0 0\n1 1 0\n0 1 0\n2 0 0\n2 1 0\n$EndNodes\n"
                 "$Elements\n2 2 1 2\n2 1 2 1\n1 1 2 3\n2 1 3 1\n2 2 5 6 3\n$EndElements\n");
  const Mesh mesh = read_gmsh_mesh(path, 2);
  ASSERT_TRUE(mesh.mixed());
  ASSERT_EQ(mesh.num_cells(), 2);
  EXPECT_EQ(mesh.type_of(0), CellType::Tri3);
  EXPECT_EQ(mesh.type_of(1), CellType::Quad4);
  EXPECT_EQ(mesh.cell_nodes(0).size(), 3u);
  EXPECT_EQ(mesh.cell_nodes(1).size(), 4u);
  EXPECT_EQ(mesh.num_nodes(), 5);
  // The two cells share the edge 2-3 (geompm's nodes 1 and 2).
  EXPECT_EQ(mesh.cell_nodes(1)[0], mesh.cell_nodes(0)[1]);
  EXPECT_EQ(mesh.cell_nodes(1)[3], mesh.cell_nodes(0)[2]);
  EXPECT_NEAR(total_measure(mesh), 1.5, 1e-14);
}

TEST(GmshImportTest, AMeshGmshMakesOfTrianglesAndRecombinedQuadrilaterals) {
  // Two unit squares side by side, the right one recombined into quadrangles: Gmsh meshes their
  // shared edge once, so the triangles and the quadrangles share its nodes.
  Mesh mesh;
  {
    GmshSession session;
    gmsh::model::add("mixed");
    namespace geo = gmsh::model::geo;
    const double h = 0.25;
    const int p1 = geo::addPoint(0, 0, 0, h), p2 = geo::addPoint(1, 0, 0, h),
              p3 = geo::addPoint(2, 0, 0, h), p4 = geo::addPoint(2, 1, 0, h),
              p5 = geo::addPoint(1, 1, 0, h), p6 = geo::addPoint(0, 1, 0, h);
    const int bottom_left = geo::addLine(p1, p2), bottom_right = geo::addLine(p2, p3),
              right = geo::addLine(p3, p4), top_right = geo::addLine(p4, p5),
              middle = geo::addLine(p5, p2), top_left = geo::addLine(p5, p6),
              left = geo::addLine(p6, p1);
    const int left_square =
        geo::addPlaneSurface({geo::addCurveLoop({bottom_left, -middle, top_left, left})});
    const int right_square =
        geo::addPlaneSurface({geo::addCurveLoop({bottom_right, right, top_right, middle})});
    geo::synchronize();
    gmsh::model::mesh::setRecombine(2, right_square);
    gmsh::model::addPhysicalGroup(2, {left_square, right_square});
    gmsh::model::mesh::generate(2);
    mesh = mesh_from_gmsh_model("mixed rectangle", 2);
  }
  ASSERT_TRUE(mesh.mixed());
  EXPECT_EQ(cell_type_names(mesh), "tri3 + quad4");
  EXPECT_NEAR(total_measure(mesh), 2.0, 1e-12);
  // Conforming: the edges only one cell has are the rectangle's outline (a hanging node on the
  // shared edge would add edges of the interface, each held once).
  std::map<std::pair<Index, Index>, int> edges;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell_nodes(c);
    for (std::size_t a = 0; a < nodes.size(); ++a) {
      const Index i = nodes[a], j = nodes[(a + 1) % nodes.size()];
      ++edges[{std::min(i, j), std::max(i, j)}];
    }
  }
  double outline = 0.0;
  for (const auto& [edge, count] : edges) {
    EXPECT_LE(count, 2);
    if (count == 1) outline += (mesh.nodes[edge.first] - mesh.nodes[edge.second]).norm();
  }
  EXPECT_NEAR(outline, 6.0, 1e-12);
}

TEST(GmshImportTest, RefusesTetrahedraAgainstAHexahedronsFace) {
  TemporaryDirectory directory;
  // A unit hexahedron and two tetrahedra on its face x = 1 (nodes 2 3 7 6), apex 9: the
  // hexahedron's bilinear face against two triangles does not conform.
  const std::string path =
      write_file(directory, "mixed3d.msh",
                 "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                 "$Nodes\n1 9 1 9\n3 1 0 9\n1\n2\n3\n4\n5\n6\n7\n8\n9\n"
                 "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n2 0.5 0.5\n"
                 "$EndNodes\n"
                 "$Elements\n2 3 1 3\n3 1 5 1\n1 1 2 3 4 5 6 7 8\n3 1 4 2\n2 2 3 7 9\n3 2 7 6 9\n"
                 "$EndElements\n");
  const std::string message = import_error(path, 3);
  EXPECT_NE(message.find("is not conforming"), std::string::npos) << message;
  EXPECT_NE(message.find("hex8"), std::string::npos) << message;
  EXPECT_NE(message.find("tet4"), std::string::npos) << message;
  EXPECT_NE(message.find("(1, 1, 1)"), std::string::npos) << message;
  EXPECT_NE(message.find("mixed3d.msh"), std::string::npos) << message;
}

TEST(GmshImportTest, APyramidBetweenAHexahedronAndTetrahedraConforms) {
  TemporaryDirectory directory;
  // The same hexahedron, a pyramid on its face x = 1 (apex 9 at x = 1.5), and two tetrahedra
  // on the pyramid's triangles 3-7-9 and 2-3-9 (out to node 10 and 11): conforming, each shared
  // face held by two cells.
  const std::string path =
      write_file(directory, "hex_pyramid_tet.msh",
                 "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                 "$Nodes\n1 11 1 11\n3 1 0 11\n1\n2\n3\n4\n5\n6\n7\n8\n9\n10\n11\n"
                 "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n1.5 0.5 0.5\n"
                 "1.5 1.5 0.5\n1.5 0.5 -0.5\n$EndNodes\n"
                 "$Elements\n3 4 1 4\n3 1 5 1\n1 1 2 3 4 5 6 7 8\n3 1 7 1\n2 2 3 7 6 9\n"
                 "3 1 4 2\n3 3 10 7 9\n4 2 3 9 11\n$EndElements\n");
  const Mesh mesh = read_gmsh_mesh(path, 3);
  ASSERT_TRUE(mesh.mixed());
  EXPECT_EQ(cell_type_names(mesh), "tet4 + hex8 + pyramid5");
  ASSERT_EQ(mesh.num_cells(), 4);
  for (Index c = 0; c < 4; ++c)
    EXPECT_EQ(static_cast<int>(mesh.cell_nodes(c).size()), nodes_per_cell(mesh.type_of(c)));
  // 1 + the pyramid's base times height / 3 + the two tetrahedra's 1/12 each.
  EXPECT_NEAR(total_measure(mesh), 1.0 + 0.5 / 3.0 + 2.0 / 12.0, 1e-14);
}

TEST(GmshImportTest, RefusesPrisms) {
  TemporaryDirectory directory;
  const std::string prism =
      write_file(directory, "prism.msh",
                 "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                 "$Nodes\n1 6 1 6\n3 1 0 6\n1\n2\n3\n4\n5\n6\n"
                 "0 0 0\n1 0 0\n0 1 0\n0 0 1\n1 0 1\n0 1 1\n$EndNodes\n"
                 "$Elements\n1 1 1 1\n3 1 6 1\n1 1 2 3 4 5 6\n$EndElements\n");
  const std::string message = import_error(prism, 3);
  EXPECT_NE(message.find("prism (wedge6)"), std::string::npos) << message;
  EXPECT_NE(message.find("pyramids (pyramid5)"), std::string::npos) << message;
  EXPECT_NE(message.find("prism.msh"), std::string::npos) << message;
}

TEST(GmshImportTest, RefusesTri6MixedWithLinearCells) {
  TemporaryDirectory directory;
  // A tri6 (corners 1 2 3, mid-sides 7 8 9) beside the quadrangle 2-5-6-3.
  const std::string tri6 =
      write_file(directory, "tri6_quad4.msh",
                 "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n"
                 "$Nodes\n1 8 1 8\n2 1 0 8\n1\n2\n3\n5\n6\n7\n8\n9\n"
                 "0 0 0\n1 0 0\n1 1 0\n2 0 0\n2 1 0\n0.5 0 0\n1 0.5 0\n0.5 0.5 0\n$EndNodes\n"
                 "$Elements\n2 2 1 2\n2 1 9 1\n1 1 2 3 7 8 9\n2 1 3 1\n2 2 5 6 3\n$EndElements\n");
  const std::string message = import_error(tri6, 2);
  EXPECT_NE(message.find("mixes tri6"), std::string::npos) << message;
}

TEST(GmshImportTest, AMeshGmshMakesOfHexahedraPyramidsAndTetrahedraConforms) {
  // The box [0, 2] x [0, 1]^2 that Gmsh meshed with hexahedra left of x = 1, tetrahedra right
  // of it and pyramids on the quadrangles of x = 1 (tests/tools/mixed_box_msh.cpp): read, found
  // conforming on import, each cell on its side.
  const std::string path = std::string(GEOMPM_SOURCE_DIR) + "/tests/unit/mesh/data/mixed_box.msh";
  const Mesh mesh = read_gmsh_mesh(path, 3);
  ASSERT_TRUE(mesh.mixed());
  EXPECT_EQ(cell_type_names(mesh), "tet4 + hex8 + pyramid5");
  EXPECT_NEAR(total_measure(mesh), 2.0, 1e-12);
  Index pyramids = 0;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    Vec3 centre = Vec3::Zero();
    for (Index n : mesh.cell_nodes(c)) centre += mesh.nodes[n] / mesh.cell_nodes(c).size();
    if (mesh.type_of(c) == CellType::Hex8) {
      EXPECT_LT(centre.x(), 1.0);
    } else {
      EXPECT_GT(centre.x(), 1.0);
    }
    if (mesh.type_of(c) == CellType::Pyramid5) {
      ++pyramids;
      // Its base on the interface, the apex inside the tetrahedra's half.
      for (int a = 0; a < 4; ++a) EXPECT_NEAR(mesh.nodes[mesh.cell_nodes(c)[a]].x(), 1.0, 1e-12);
      EXPECT_GT(mesh.nodes[mesh.cell_nodes(c)[4]].x(), 1.0);
    }
  }
  EXPECT_EQ(pyramids, 4);  // one on each of the interface's 2 x 2 quadrangles
  // Conforming: every face is held by two cells, or by one on the box's outline (area 10).
  std::map<std::vector<Index>, std::pair<int, double>> faces;
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell_nodes(c);
    for (const auto& corners : cell_corner_faces(mesh.type_of(c))) {
      std::vector<Index> key;
      std::vector<Vec3> x;
      for (int a : corners) key.push_back(nodes[a]), x.push_back(mesh.nodes[nodes[a]]);
      std::sort(key.begin(), key.end());
      const Vec3 area = x.size() == 3 ? Vec3(0.5 * (x[1] - x[0]).cross(x[2] - x[0]))
                                      : Vec3(0.5 * (x[2] - x[0]).cross(x[3] - x[1]));
      auto& [count, measure] = faces[key];
      ++count;
      measure = area.norm();
    }
  }
  double outline = 0.0;
  for (const auto& [key, use] : faces) {
    EXPECT_LE(use.first, 2);
    if (use.first == 1) outline += use.second;
  }
  EXPECT_NEAR(outline, 10.0, 1e-12);
  expect_groups_on_their_sides(mesh, Vec3::Zero(), Vec3(2, 1, 1), false);
  EXPECT_EQ(mesh.cell_groups.at("hexahedra").size(), 8u);
}

TEST(GmshImportTest, UnsupportedCellType) {
  TemporaryDirectory directory;
  // One 9-node quadrangle (Gmsh type 10) on a 3 x 3 grid of nodes.
  std::string nodes = "$Nodes\n1 9 1 9\n2 1 0 9\n";
  for (int n = 1; n <= 9; ++n) nodes += std::to_string(n) + "\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i)
      nodes += std::to_string(0.5 * i) + " " + std::to_string(0.5 * j) + " 0\n";
  const std::string path = write_file(
      directory, "quad9.msh",
      "$MeshFormat\n4.1 0 8\n$EndMeshFormat\n" + nodes +
          "$EndNodes\n$Elements\n1 1 1 1\n2 1 10 1\n1 1 3 9 7 2 6 8 4 5\n$EndElements\n");
  const std::string message = import_error(path, 2);
  EXPECT_NE(message.find("unsupported"), std::string::npos) << message;
  EXPECT_NE(message.find("10"), std::string::npos) << message;
}

TEST(GmshImportTest, NoCellsOfTheRequestedDimension) {
  TemporaryDirectory directory;
  const std::string path = write_file(directory, "flat.msh", square_file("0", two_triangles));
  const std::string message = import_error(path, 3);
  EXPECT_NE(message.find("no 3D cells"), std::string::npos) << message;
}

TEST(GmshImportTest, DimensionMustBeTwoOrThree) {
  TemporaryDirectory directory;
  const std::string path = write_file(directory, "good.msh", square_file("0", two_triangles));
  EXPECT_FALSE(import_error(path, 1).empty());
}

TEST(GmshImportTest, ImportIsRepeatableAfterAnError) {
  // A failed import must leave Gmsh ready for the next one (the session is cleaned up).
  TemporaryDirectory directory;
  const std::string bad = write_file(directory, "bad.msh", "hello world\n");
  const std::string good = write_file(directory, "good.msh", square_file("0", two_triangles));
  for (int k = 0; k < 3; ++k) {
    EXPECT_THROW(read_gmsh_mesh(bad, 2), InputError);
    EXPECT_EQ(read_gmsh_mesh(good, 2).num_cells(), 2);
  }
}

TEST(GmshImportTest, FileThatCrashesGmshsReaderIsAnInputError) {
  // Found by fuzz/fuzz_mesh_reader: the footing example's mesh with a block of node coordinates
  // repeated, so that the $Nodes section no longer matches its counts. Gmsh 4.8's MSH4 reader
  // reads out of bounds on it (a segmentation fault); geompm reads meshes in a child process, so
  // this is bad input with a message, and the next read works.
  const std::string damaged =
      std::string(GEOMPM_SOURCE_DIR) + "/tests/unit/mesh/data/msh4_nodes_block_repeated.msh";
  const std::string message = import_error(damaged, 2);
  EXPECT_NE(message.find("damaged"), std::string::npos) << message;
  TemporaryDirectory directory;
  const std::string good = write_file(directory, "good.msh", square_file("0", two_triangles));
  EXPECT_EQ(read_gmsh_mesh(good, 2).num_cells(), 2);
}

TEST(GmshImportTest, NumericLocaleIsLeftAsItWas) {
  // Gmsh switches LC_NUMERIC to "C"; a session must put the caller's setting back.
  const std::string before = std::setlocale(LC_NUMERIC, nullptr);
  if (!std::setlocale(LC_NUMERIC, "C.UTF-8")) GTEST_SKIP() << "no C.UTF-8 locale";
  const std::string chosen = std::setlocale(LC_NUMERIC, nullptr);
  TemporaryDirectory directory;
  const std::string good = write_file(directory, "good.msh", square_file("0", two_triangles));
  EXPECT_EQ(read_gmsh_mesh(good, 2).num_cells(), 2);
  EXPECT_EQ(std::string(std::setlocale(LC_NUMERIC, nullptr)), chosen);
  std::setlocale(LC_NUMERIC, before.c_str());
}

}  // namespace
}  // namespace geompm
