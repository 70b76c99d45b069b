// The ghost penalty of the body's edge cells (docs/theory.md eq. 6.3) on a row of three cells
// (unit squares or cubes, or the triangles and tetrahedra the generator splits them into): the
// first two hold points, the third is an active cell without any, so the cells of the middle
// column are edge cells and the faces on x = 1 carry the penalty, those on x = 2 (to the empty
// cell) none. A field with a kink on x = 1 (grad u . n jumps by 1) costs
// gamma E h_F |F| per face, the closed form of eq. 6.3; a linear field costs nothing. The middle
// column's points fill 0.3 of it, under the default limit of 0.5.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <string>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/mesh_topology.hpp"
#include "geompm/mesh/structured_mesh.hpp"
#include "geompm/physics/ghost_penalty.hpp"

namespace geompm {
namespace {

struct Row {
  Mesh mesh;
  MeshTopology topology;
  std::vector<Index> active_cells, node_to_active;
  std::vector<double> modulus, fill;  // per active cell; a fill of 0: no points
};

/// Three cells of size `size` in a row along axis `along` (0: x, 1: y) from `origin`: the first
/// two hold points (moduli 7e4 and 2e4; fills 1 and 0.3), the third none.
Row row_of_three(CellType type, Diagonals diagonals = Diagonals::Alternating,
                 const Vec3& origin = Vec3::Zero(), double size = 1.0, int along = 0) {
  StructuredMeshSpec spec;
  spec.cell_type = type;
  spec.diagonals = diagonals;
  spec.origin = origin;
  for (int i = 0; i < 3; ++i)
    spec.axes[i] = {i == along ? AxisSegment{3.0 * size, 3, 1.0} : AxisSegment{size, 1, 1.0}};
  Row row;
  row.mesh = generate_structured_mesh(spec);
  row.topology = build_mesh_topology(row.mesh);
  for (Index c = 0; c < row.mesh.num_cells(); ++c) {
    row.active_cells.push_back(c);
    Vec3 centre = Vec3::Zero();
    for (Index n : row.mesh.cell_nodes(c)) centre += row.mesh.nodes[n];
    centre /= row.mesh.nodes_per_cell();
    const double position = (centre(along) - origin(along)) / size;
    const bool occupied = position < 2.0, first = position < 1.0;
    // A stiffer material in the first cell: the face takes the smaller modulus.
    row.modulus.push_back(occupied ? (first ? 7.0e4 : 2.0e4) : 0.0);
    row.fill.push_back(occupied ? (first ? 1.0 : 0.3) : 0.0);
  }
  row.node_to_active.resize(row.mesh.num_nodes());
  for (Index n = 0; n < row.mesh.num_nodes(); ++n) row.node_to_active[n] = n;
  return row;
}

std::vector<NodeBlock> faces_of(const Row& row, double gamma, bool radial = false,
                                double fill_limit = 0.5) {
  return ghost_penalty_faces(row.mesh, row.topology, row.active_cells, row.node_to_active,
                             {row.modulus, row.fill}, {gamma, fill_limit, radial});
}

/// sum over faces of u^T G u for the nodal scalar field u(x).
template <class Field>
double penalty_energy(const Row& row, const std::vector<NodeBlock>& faces, Field&& u) {
  double energy = 0.0;
  for (const NodeBlock& face : faces) {
    Eigen::VectorXd values(face.nodes.size());
    for (std::size_t a = 0; a < face.nodes.size(); ++a)
      values(a) = u(row.mesh.nodes[face.nodes[a]]);
    energy += values.dot(face.weight * values);
  }
  return energy;
}

double kink(const Vec3& x, double at) { return std::max(0.0, x.x() - at); }

struct Case {
  CellType type;
  Diagonals diagonals;
  double cell_size;  // h_F of unit cells: (cell measure)^(1/dim)
};

// Cells of size 1 and 2 (h_F and |F| scale with it: gamma E h_F |F| by size^dim).
TEST(GhostPenalty, AKinkAcrossAnEdgeCellsFaceCostsGammaEhTimesTheFacesArea) {
  const double gamma = 0.05, E = 2.0e4;  // E: the smaller of the two cells' moduli
  const Case cases[] = {
      {CellType::Quad4, Diagonals::Alternating, 1.0},
      {CellType::Tri3, Diagonals::Alternating, std::sqrt(0.5)},
      {CellType::Hex8, Diagonals::Alternating, 1.0},
      {CellType::Tet4, Diagonals::Alternating, std::cbrt(1.0 / 6.0)},
  };
  for (const Case& c : cases)
    for (const double size : {1.0, 2.0}) {
      SCOPED_TRACE(std::string(to_string(c.type)) + " of size " + std::to_string(size));
      const Row row = row_of_three(c.type, c.diagonals, Vec3::Zero(), size);
      const int dim = row.mesh.dim();
      const auto faces = faces_of(row, gamma);
      ASSERT_FALSE(faces.empty());
      const double expected = gamma * E * c.cell_size * std::pow(size, dim);
      EXPECT_NEAR(penalty_energy(row, faces, [&](const Vec3& x) { return kink(x, size); }),
                  expected, 1e-10 * expected);
      // No face to the empty cell: a kink on x = 2 size costs nothing.
      EXPECT_NEAR(penalty_energy(row, faces, [&](const Vec3& x) { return kink(x, 2.0 * size); }),
                  0.0, 1e-10 * expected);
      // A linear field (translation, rotation, uniform strain) has no jump anywhere.
      for (const NodeBlock& face : faces) {
        Eigen::VectorXd linear(face.nodes.size());
        for (std::size_t a = 0; a < face.nodes.size(); ++a) {
          const Vec3& x = row.mesh.nodes[face.nodes[a]];
          linear(a) = 0.3 + 1.7 * x.x() - 0.8 * x.y() + 0.4 * x.z();
        }
        EXPECT_LT((face.weight * linear).norm(), 1e-10 * gamma * E);
        EXPECT_LT((face.weight - face.weight.transpose()).norm(), 1e-12 * face.weight.norm());
        const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(face.weight);
        EXPECT_GT(eigen.eigenvalues().minCoeff(), -1e-10 * face.weight.norm());
      }
    }
}

// A jump that varies along the face checks the face's quadrature: u = (x - 1)(1 + y) beyond
// x = 1 (bilinear) jumps by 1 + y, so the face costs gamma E h int_0^1 (1 + y)^2 dy = 7/3 gamma E
// h; on hexahedra u = (x - 1)(1 + y)(1 + z) costs (7/3)^2 gamma E h. A one-point rule, misplaced
// points or a wrong area element would miss it.
TEST(GhostPenalty, AJumpVaryingAlongTheFaceIsIntegratedExactly) {
  const double gamma = 0.05, E = 2.0e4;
  const Row quads = row_of_three(CellType::Quad4);
  EXPECT_NEAR(penalty_energy(quads, faces_of(quads, gamma),
                             [](const Vec3& x) { return kink(x, 1.0) * (1.0 + x.y()); }),
              gamma * E * 7.0 / 3.0, 1e-10 * gamma * E);
  const Row hexes = row_of_three(CellType::Hex8);
  EXPECT_NEAR(
      penalty_energy(hexes, faces_of(hexes, gamma),
                     [](const Vec3& x) { return kink(x, 1.0) * (1.0 + x.y()) * (1.0 + x.z()); }),
      gamma * E * 49.0 / 9.0, 1e-10 * gamma * E);
}

// Crossed triangles: the triangles on x = 1 meet at the rectangles' centres and touch no node of
// the empty column, so no face on x = 1 belongs to an edge cell - only the faces of the middle
// column's triangles on x = 2's side do; the linear field is still free.
TEST(GhostPenalty, OnlyFacesOfEdgeCellsCarryIt) {
  const Row row = row_of_three(CellType::Tri3, Diagonals::Crossed);
  const auto faces = faces_of(row, 0.05);
  ASSERT_FALSE(faces.empty());
  EXPECT_NEAR(penalty_energy(row, faces, [](const Vec3& x) { return kink(x, 1.0); }), 0.0, 1e-9);
  for (const NodeBlock& face : faces)
    for (Index node : face.nodes) EXPECT_GT(row.mesh.nodes[node].x(), 1.0 - 1e-12);
}

// Without buffer cells the cell beyond the body is not active, and the body's last cells are edge
// cells all the same; a body that fills the mesh has none.
TEST(GhostPenalty, EdgeCellsNeedNoBufferCells) {
  Row row = row_of_three(CellType::Quad4);
  Row without_buffer = row;
  without_buffer.active_cells = {0, 1};
  without_buffer.modulus = {row.modulus[0], row.modulus[1]};
  without_buffer.fill = {1.0, 0.3};
  const auto kinked = [](const Vec3& x) { return kink(x, 1.0); };
  EXPECT_NEAR(penalty_energy(without_buffer, faces_of(without_buffer, 0.05), kinked),
              penalty_energy(row, faces_of(row, 0.05), kinked), 1e-9);
  row.modulus = {7.0e4, 2.0e4, 2.0e4};
  row.fill = {1.0, 0.3, 0.3};
  EXPECT_TRUE(faces_of(row, 0.05).empty());
}

// An edge cell its points fill beyond the limit carries none: its nodes are well supported, and a
// kink beside it is the body's own (the fan at a footing's edge). A limit of 1 takes every edge
// cell; a cell filled exactly to the limit counts. (The face on x = 1 of the other tests joins a
// sparse edge cell to a full cell, which is no edge cell: one sparse side is enough.)
TEST(GhostPenalty, WellFilledEdgeCellsCarryNone) {
  const double gamma = 0.05, E = 2.0e4;
  Row row = row_of_three(CellType::Quad4);
  row.fill[1] = 0.8;
  const auto kinked = [](const Vec3& x) { return kink(x, 1.0); };
  EXPECT_TRUE(faces_of(row, gamma).empty());
  EXPECT_TRUE(faces_of(row, gamma, false, 0.79).empty());
  EXPECT_NEAR(penalty_energy(row, faces_of(row, gamma, false, 0.8), kinked), gamma * E,
              1e-10 * gamma * E);
  EXPECT_NEAR(penalty_energy(row, faces_of(row, gamma, false, 1.0), kinked), gamma * E,
              1e-10 * gamma * E);
}

// Axisymmetry weights the face by its radius (per radian): a vertical face at r = 3, and a
// horizontal one over 2 <= r <= 3 with a jump of 1 + r: int_2^3 (1 + r)^2 r dr = 377/12.
TEST(GhostPenalty, AxisymmetricFacesAreWeightedByTheirRadius) {
  const double gamma = 0.05, E = 2.0e4;
  const Row row = row_of_three(CellType::Quad4, Diagonals::Alternating, Vec3(2.0, 0.0, 0.0));
  EXPECT_NEAR(
      penalty_energy(row, faces_of(row, gamma, true), [](const Vec3& x) { return kink(x, 3.0); }),
      gamma * E * 1.0 * 3.0, 1e-10 * gamma * E);
  const Row column =
      row_of_three(CellType::Quad4, Diagonals::Alternating, Vec3(2.0, 0.0, 0.0), 1.0, 1);
  EXPECT_NEAR(
      penalty_energy(column, faces_of(column, gamma, true),
                     [](const Vec3& x) { return std::max(0.0, x.y() - 1.0) * (1.0 + x.x()); }),
      gamma * E * 377.0 / 12.0, 1e-10 * gamma * E);
}

TEST(GhostPenalty, QuadraticTrianglesAreRefused) {
  Row row = row_of_three(CellType::Tri3);
  StructuredMeshSpec spec;
  spec.cell_type = CellType::Tri6;
  spec.axes = {std::vector<AxisSegment>{{3.0, 3, 1.0}}, {{1.0, 1, 1.0}}, {}};
  row.mesh = generate_structured_mesh(spec);
  EXPECT_THROW(faces_of(row, 0.05), std::invalid_argument);
}

}  // namespace
}  // namespace geompm
