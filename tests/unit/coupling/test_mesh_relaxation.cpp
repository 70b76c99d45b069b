// The FEM region's cells and nodes, the mesh relaxation after a step (docs/theory.md §19.3) and the
// mesh quality it reports, on a generated 4 x 4 grid of unit cells whose lower half is FEM.
#include <gtest/gtest.h>

#include <cmath>

#include "geompm/coupling/fem_region.hpp"
#include "geompm/coupling/mesh_quality.hpp"
#include "geompm/coupling/mesh_relaxation.hpp"
#include "geompm/mesh/gmsh_import.hpp"
#include "geompm/mesh/structured_mesh.hpp"

namespace geompm {
namespace {

Mesh unit_grid(int n) {
  StructuredMeshSpec spec;
  spec.cell_type = CellType::Quad4;
  spec.axes[0] = {AxisSegment{static_cast<double>(n), n, 1.0}};
  spec.axes[1] = {AxisSegment{static_cast<double>(n), n, 1.0}};
  return generate_structured_mesh(spec);
}

// The cells whose centroid lies below y = 2 are FEM.
std::vector<CellKind> lower_half_fem(const Mesh& mesh) {
  std::vector<CellKind> kinds(mesh.num_cells(), CellKind::Mpm);
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    double y = 0.0;
    for (Index a : mesh.cell_nodes(c)) y += mesh.nodes[a].y() / 4.0;
    if (y < 2.0) kinds[c] = CellKind::Fem;
  }
  return kinds;
}

TEST(FemRegion, KnowsItsCellsAndNodes) {
  const Mesh mesh = unit_grid(4);
  const FemRegion region(mesh, lower_half_fem(mesh));
  EXPECT_EQ(region.cells().size(), 8u);
  EXPECT_EQ(region.gauss_begin(1), 4);  // quad4: 2 x 2 Gauss points each
  EXPECT_EQ(region.gauss_begin(8), 32);
  Index fem_nodes = 0;
  for (char f : region.fem_node()) fem_nodes += f;
  EXPECT_EQ(fem_nodes, 15);  // the nodes at y = 0, 1, 2
}

TEST(MeshRelaxation, FindsTheBoundaryNodes) {
  const Mesh mesh = unit_grid(4);
  const std::vector<char> boundary = boundary_nodes(mesh);
  Index count = 0;
  for (Index a = 0; a < mesh.num_nodes(); ++a) {
    const Vec3& x = mesh.nodes[a];
    const bool on_edge = x.x() == 0.0 || x.x() == 4.0 || x.y() == 0.0 || x.y() == 4.0;
    EXPECT_EQ(boundary[a] != 0, on_edge) << "node at " << x.transpose();
    count += boundary[a];
  }
  EXPECT_EQ(count, 16);
}

TEST(MeshRelaxation, FindsTheBoundaryNodesOfAMeshOfHexahedraPyramidsAndTetrahedra) {
  // The box [0, 2] x [0, 1]^2 of tests/unit/mesh/data/mixed_box.msh: a hexahedron's face against
  // a pyramid's base and a pyramid's triangle against a tetrahedron's are inner faces, so only the
  // nodes on the box's sides are boundary nodes.
  const Mesh mesh =
      read_gmsh_mesh(std::string(GEOMPM_SOURCE_DIR) + "/tests/unit/mesh/data/mixed_box.msh", 3);
  ASSERT_EQ(cell_type_names(mesh), "tet4 + hex8 + pyramid5");
  const std::vector<char> boundary = boundary_nodes(mesh);
  Index count = 0;
  for (Index a = 0; a < mesh.num_nodes(); ++a) {
    const Vec3& x = mesh.nodes[a];
    const bool on_side = std::abs(x.x()) < 1e-12 || std::abs(x.x() - 2.0) < 1e-12 ||
                         std::abs(x.y()) < 1e-12 || std::abs(x.y() - 1.0) < 1e-12 ||
                         std::abs(x.z()) < 1e-12 || std::abs(x.z() - 1.0) < 1e-12;
    EXPECT_EQ(boundary[a] != 0, on_side) << "node at " << x.transpose();
    count += boundary[a];
  }
  EXPECT_LT(count, mesh.num_nodes());
  // The cells' shape: the hexahedra are cubes, the rest Gmsh's tetrahedra and pyramids.
  const MeshQuality quality = mesh_quality(mesh, {});
  EXPECT_GT(quality.smallest_angle, 10.0);
  EXPECT_LT(quality.smallest_angle, 60.0);
}

TEST(MeshRelaxation, KeepsTheFemNodesAndResetsTheMpmMeshWhenTheyDidNotMove) {
  Mesh mesh = unit_grid(4);
  const FemRegion region(mesh, lower_half_fem(mesh));
  const MeshRelaxation relaxation(mesh, region);
  EXPECT_EQ(relaxation.free_nodes(), 3);  // the interior nodes at y = 3
  // The MPM nodes were carried by a step (as the points' convection would): relaxation brings them
  // back exactly while no FEM node moved.
  const std::vector<Vec3> initial = mesh.nodes;
  for (Index a = 0; a < mesh.num_nodes(); ++a)
    if (!region.fem_node()[a]) mesh.nodes[a] += Vec3(0.1, -0.2, 0.0);
  relaxation.relax(mesh);
  for (Index a = 0; a < mesh.num_nodes(); ++a)
    if (!region.fem_node()[a]) {
      EXPECT_EQ(mesh.nodes[a], initial[a]);
    }
}

TEST(MeshRelaxation, FollowsTheInterfaceAndHoldsTheFemRegion) {
  Mesh mesh = unit_grid(4);
  const FemRegion region(mesh, lower_half_fem(mesh));
  const MeshRelaxation relaxation(mesh, region);
  // The FEM region settles by 0.3 at the interface (y = 2) and less below it.
  for (Index a = 0; a < mesh.num_nodes(); ++a)
    if (region.fem_node()[a]) mesh.nodes[a].y() -= 0.15 * mesh.nodes[a].y();
  const std::vector<Vec3> moved = mesh.nodes;
  relaxation.relax(mesh);
  for (Index a = 0; a < mesh.num_nodes(); ++a) {
    const Vec3& X = region.initial_nodes()[a];
    if (region.fem_node()[a]) {
      EXPECT_EQ(mesh.nodes[a], moved[a]);  // the FEM region is never relaxed
    } else if (X.y() == 4.0 || X.x() == 0.0 || X.x() == 4.0) {
      EXPECT_EQ(mesh.nodes[a], X);  // the outer boundary is held
    } else {
      // An interior node at y = 3: the discrete harmonic displacement between the interface
      // (-0.3) and the top (0) lies strictly between them, and the solve keeps x by symmetry
      // for the middle node.
      EXPECT_LT(mesh.nodes[a].y() - X.y(), 0.0);
      EXPECT_GT(mesh.nodes[a].y() - X.y(), -0.3);
      if (X.x() == 2.0) {
        EXPECT_NEAR(mesh.nodes[a].x(), 2.0, 1e-14);
      }
    }
  }
}

TEST(MeshQuality, MeasuresAnglesAndAspectRatios) {
  Mesh mesh = unit_grid(2);
  MeshQuality q = mesh_quality(mesh);
  EXPECT_NEAR(q.smallest_angle, 90.0, 1e-12);
  EXPECT_NEAR(q.largest_aspect_ratio, 1.0, 1e-12);
  // Stretch the mesh to 2 x 1 cells and shear the middle node: the angles at it close.
  for (Vec3& x : mesh.nodes) x.x() *= 2.0;
  EXPECT_NEAR(mesh_quality(mesh).largest_aspect_ratio, 2.0, 1e-12);
  for (Vec3& x : mesh.nodes)
    if (x.x() == 2.0 && x.y() == 1.0) x.x() += 1.0;
  q = mesh_quality(mesh);
  // The smallest angle is now at the moved node (3, 1) in the lower left cell: between the edges
  // to (0, 1) and to (2, 0), atan(1 / 1) = 45 degrees.
  EXPECT_NEAR(q.smallest_angle, 45.0, 1e-12);
}

}  // namespace
}  // namespace geompm
