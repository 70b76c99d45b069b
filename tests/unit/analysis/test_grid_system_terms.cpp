// The terms of the grid system one by one: inadmissible steps and the point the grid names, the
// cell-averaged volume change (F-bar), the incremental pressure equation, the pressure
// stabilisation's floor, the sparse-node springs, the ghost penalty, uniform stress from a linear
// field with DDMP and GIMP, and GIMP's mapping of mass and loads.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>

#include <functional>
#include <map>
#include <memory>
#include <random>

#include "geompm/interpolation/gimp_weights.hpp"
#include "geompm/physics/exact_pressure_projection.hpp"
#include "grid_harness.hpp"
#include "grid_test_choices.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

using testing::mixed_tresca;
using testing::scatter_points;

// A step that turns points inside out is refused, and the grid names the lowest-numbered such
// point for the failure message, whichever thread met it first; an admissible step names none.
TEST(GridSystemInadmissible, NamesTheLowestPointThatTurnedInsideOut) {
  auto spec = testing::read_example("oedometer/oedometer.yaml");
  auto model = build_model(spec);
  GridSettings settings;
  settings.kinematics = spec.kinematics;
  testing::GridHarness grid(model->mesh, model->topology, model->material_pointers(), settings);
  grid.initialise(model->points);
  grid.set_constraints(std::vector<char>(grid.num_dofs(), 0));
  const int dim = grid.dim();
  Vector du = Vector::Zero(grid.num_dofs());
  Vector f;
  ASSERT_TRUE(grid.internal_force(model->points, du, f, nullptr));
  EXPECT_EQ(grid.inadmissible_point(), -1);
  // du_x = -3 x: dF_xx = -2 at every point, det dF < 0 everywhere.
  for (std::size_t a = 0; a < grid.active_nodes().size(); ++a)
    du(static_cast<Index>(a) * dim) = -3.0 * model->mesh.nodes[grid.active_nodes()[a]].x();
  EXPECT_FALSE(grid.internal_force(model->points, du, f, nullptr));
  EXPECT_EQ(grid.inadmissible_point(), 0);
}

// A material whose stress update fails (as a return mapping that does not converge,
// StressUpdate::converged) beyond a trial strain of norm `limit`, and is the wrapped one's below.
class FailingBeyond final : public Material {
 public:
  FailingBeyond(const Material& inner, double limit) : inner_(inner), limit_(limit) {}
  void update(const Mat3& eps, const InternalVariables& internal_n,
              StressUpdate& out) const override {
    inner_.update(eps, internal_n, out);
    if (eps.norm() > limit_) out.converged = false;
  }
  double density() const override { return inner_.density(); }
  double reference_modulus() const override { return inner_.reference_modulus(); }
  ElasticModuli elastic_moduli(const InternalVariables& internal) const override {
    return inner_.elastic_moduli(internal);
  }
  double strain_energy(const Mat3& eps) const override { return inner_.strain_energy(eps); }
  const char* model_name() const override { return "failing"; }

 private:
  const Material& inner_;
  double limit_;
};

// A point whose stress update fails makes the step inadmissible as a point turned inside out does
// (Newton cuts the step back), and the grid says which of the two it was, for the message; the
// same point with its update within reach is admissible, so the check can fail.
TEST(GridSystemInadmissible, SaysWhenAPointsStressUpdateFailed) {
  auto spec = testing::read_example("oedometer/oedometer.yaml");
  auto model = build_model(spec);
  std::vector<std::unique_ptr<Material>> failing;
  std::vector<const Material*> materials;
  for (const Material* m : model->material_pointers()) {
    failing.push_back(std::make_unique<FailingBeyond>(*m, 1e-3));
    materials.push_back(failing.back().get());
  }
  GridSettings settings;
  settings.kinematics = spec.kinematics;
  testing::GridHarness grid(model->mesh, model->topology, materials, settings);
  grid.initialise(model->points);
  grid.set_constraints(std::vector<char>(grid.num_dofs(), 0));
  const int dim = grid.dim();
  Vector du = Vector::Zero(grid.num_dofs()), f;
  const auto stretch = [&](double rate) {
    for (std::size_t a = 0; a < grid.active_nodes().size(); ++a)
      du(static_cast<Index>(a) * dim) = rate * model->mesh.nodes[grid.active_nodes()[a]].x();
  };
  stretch(1e-4);  // eps_xx ~ 1e-4 at every point: within the limit
  EXPECT_TRUE(grid.internal_force(model->points, du, f, nullptr));
  EXPECT_EQ(grid.inadmissible_point(), -1);
  stretch(1e-2);  // eps_xx ~ 1e-2: every point's update fails, no volume is lost
  EXPECT_FALSE(grid.internal_force(model->points, du, f, nullptr));
  EXPECT_EQ(grid.inadmissible_point(), 0);
  EXPECT_TRUE(grid.inadmissible_by_stress_update());
  stretch(-3.0);  // det dF < 0 before the material is reached
  EXPECT_FALSE(grid.internal_force(model->points, du, f, nullptr));
  EXPECT_EQ(grid.inadmissible_point(), 0);
  EXPECT_FALSE(grid.inadmissible_by_stress_update());
}

// The cell-averaged volume change (F-bar, docs/theory.md eqs. 12.1-12.3), of mixed or displacement
// points: after a random increment every point of a cell has changed volume by the same ratio,
// and the cell's points together by exactly as much as without the average
// (sum_q v_q,n det dF_q), while each point's domain keeps its own deformation; with `per_point`
// the ratios differ, so the check can fail.
void check_volume_average(const std::string& example, bool average, bool mixed = true) {
  auto spec = testing::read_example(example);
  for (auto& material : spec.materials) {
    material.model = mixed_tresca.model;
    material.parameters = mixed_tresca.parameters;
  }
  auto model = build_model(spec);
  GridSettings settings;
  settings.kinematics = spec.kinematics;
  settings.mixed.assign(spec.materials.size(), mixed);
  settings.volume_average.assign(spec.materials.size(), average);
  testing::GridHarness grid(model->mesh, model->topology, model->material_pointers(), settings);
  grid.initialise(model->points);
  grid.set_constraints(std::vector<char>(grid.num_dofs(), 0));
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vector du = Vector::Zero(grid.num_dofs());
  const Index displacements =
      static_cast<Index>(grid.active_nodes().size()) * static_cast<Index>(grid.dim());
  for (Index d = 0; d < displacements; ++d) du(d) = 2e-3 * u(rng);
  MaterialPoints own = model->points, averaged = model->points;
  settings.volume_average.assign(spec.materials.size(), 0);
  testing::GridHarness per_point(model->mesh, model->topology, model->material_pointers(),
                                 settings);
  per_point.initialise(own);
  ASSERT_TRUE(per_point.commit_state(own, du));
  ASSERT_TRUE(grid.commit_state(averaged, du));
  // Points are sorted by cell in both copies (initialise sorted them the same way).
  double largest_spread = 0.0;
  for (Index p = 0; p < averaged.size();) {
    Index end = p;
    double start = 0.0, with_average = 0.0, without = 0.0;
    double low = 1e300, high = -1e300;
    for (; end < averaged.size() && averaged.cell[end] == averaged.cell[p]; ++end) {
      const double ratio = averaged.volume[end] / model->points.volume[end];
      low = std::min(low, ratio);
      high = std::max(high, ratio);
      start += model->points.volume[end];
      with_average += averaged.volume[end];
      without += own.volume[end];
    }
    largest_spread = std::max(largest_spread, high - low);
    if (average) {
      EXPECT_NEAR(with_average, without, 1e-12 * start);
    }
    // Each point's domain follows its own motion (eq. 12.7), not the averaged F^ its material
    // sees: the domain's deformation gradient is the one each point has without the average.
    for (Index q = p; q < end; ++q)
      EXPECT_LT((averaged.domain_deformation(q, grid.dim()) - own.deformation_gradient[q]).norm(),
                1e-12);
    p = end;
  }
  if (average)
    EXPECT_LT(largest_spread, 1e-12);
  else
    EXPECT_GT(largest_spread, 1e-4);
}

TEST(GridSystemVolumeAverage, PointsOfACellShareItsVolumeChange) {
  check_volume_average("oedometer/oedometer.yaml", true);
  check_volume_average("column/column_3d.yaml", true);
}
TEST(GridSystemVolumeAverage, WithoutItEachPointKeepsItsOwn) {
  check_volume_average("oedometer/oedometer.yaml", false);
}
TEST(GridSystemVolumeAverage, DisplacementPointsShareItToo) {
  check_volume_average("oedometer/oedometer.yaml", true, false);
  check_volume_average("column/column_3d.yaml", true, false);
}

// The oedometer example with its soil made mixed Tresca clay.
auto mixed_tresca_oedometer() {
  auto spec = testing::read_example("oedometer/oedometer.yaml");
  for (auto& material : spec.materials) {
    material.model = mixed_tresca.model;
    material.parameters = mixed_tresca.parameters;
  }
  return spec;
}

// The incremental pressure equation (theory eqs. 11.8-11.9): a step starts in balance with what
// the last one committed, however far the points' own volumes have drifted from the field's
// pressure. The points carry a uniform pressure p0 (their total stress) while their elastic
// volumes differ by up to 1 %, so their material pressures scatter by about K / 100 around it:
// the total equation (11.2) sees that scatter as a residual of the pressure rows at zero
// increment, which Newton would turn into a pressure field varying within the cells (the
// checkerboard of docs/validation.md §4); the incremental one sees none once each point carries
// the mismatch it committed.
TEST(GridSystemIncrementalPressure, AStepStartsInBalanceWithTheMismatchThePointsCarry) {
  const auto spec = mixed_tresca_oedometer();
  auto model = build_model(spec);
  const double p0 = 3.0;
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (Index p = 0; p < model->points.size(); ++p) {
    model->points.stress[p] = -p0 * Mat3::Identity();
    const double stretch = 1.0 + 0.005 * u(rng);  // plane strain: J_e = stretch^2
    model->points.elastic_left_cauchy_green[p] =
        Vec3(stretch * stretch, stretch * stretch, 1.0).asDiagonal();
  }
  auto pressure_rows = [&](const MaterialPoints& points, bool incremental) {
    GridSettings settings;
    settings.kinematics = spec.kinematics;
    settings.mixed.assign(spec.materials.size(), 1);
    settings.volume_average.assign(spec.materials.size(), 0);
    settings.mixed_incremental_pressure = incremental;
    testing::GridHarness grid(model->mesh, model->topology, model->material_pointers(), settings);
    MaterialPoints copy = points;
    grid.initialise(copy);
    grid.set_constraints(std::vector<char>(grid.num_dofs(), 0));
    const Vector zero = Vector::Zero(grid.num_dofs());
    Vector f;
    EXPECT_TRUE(grid.internal_force(copy, zero, f, nullptr));
    const Index first = grid.pressure_dof(0);
    const Vector rows = f.tail(f.size() - first);
    EXPECT_TRUE(grid.commit_state(copy, zero));
    return std::pair{rows.lpNorm<Eigen::Infinity>(), copy};
  };
  // The total equation: the scattered material pressures force the pressure rows.
  const auto [total, unused] = pressure_rows(model->points, false);
  // The incremental one, after a step at rest has committed each point's mismatch.
  const auto [first_step, committed] = pressure_rows(model->points, true);
  const auto [next_step, unused_again] = pressure_rows(committed, true);
  EXPECT_GT(total, 1e-6);
  EXPECT_NEAR(first_step, total, 1e-9 * total);  // nothing carried yet: the same residual
  EXPECT_LT(next_step, 1e-10 * total);
}

// The floor of the pressure stabilisation (theory eq. 11.10). With every point of a cell on the
// cell's horizontal mid-line (and no empty cells), the pressure that alternates from one row of
// nodes to the next is zero at every point: the points' sum (11.5) and the pressure rows' own N N^T
// / K term do not see it, and it is a null mode of the pressure block. The exactly integrated
// projection does see it, so with a floor the block resists it, while a pressure constant over the
// mesh still costs nothing more than before.
TEST(GridSystemPressureStabilisation, TheFloorResistsAModeThePointsCannotSee) {
  const auto spec = mixed_tresca_oedometer();
  auto model = build_model(spec);
  for (Index p = 0; p < model->points.size(); ++p) {  // onto the mid-line of the point's cell
    const auto nodes = model->mesh.cell_nodes(model->points.cell[p]);
    double middle = 0.0;
    for (const Index n : nodes) middle += model->mesh.nodes[n].y() / nodes.size();
    model->points.position[p].y() = middle;
    model->points.local[p].y() = 0.0;
  }
  auto pressure_energy = [&](double floor, auto&& mode) {
    GridSettings settings;
    settings.kinematics = spec.kinematics;
    settings.mixed.assign(spec.materials.size(), 1);
    settings.volume_average.assign(spec.materials.size(), 0);
    settings.pressure_stabilisation_floor = floor;
    settings.buffer_layers = 0;  // no empty cells, whose regularisation (11.7) would see the mode
    testing::GridHarness grid(model->mesh, model->topology, model->material_pointers(), settings);
    MaterialPoints points = model->points;
    grid.initialise(points);
    grid.set_constraints(std::vector<char>(grid.num_dofs(), 0));
    Vector f;
    SparseMatrix K;
    EXPECT_TRUE(grid.internal_force(points, Vector::Zero(grid.num_dofs()), f, &K));
    Vector x = Vector::Zero(K.cols());
    for (Index a = 0; a < static_cast<Index>(grid.active_nodes().size()); ++a)
      x(grid.free_index()[grid.pressure_dof(a)]) = mode(model->mesh.nodes[grid.active_nodes()[a]]);
    return x.dot(K * x) / x.squaredNorm();
  };
  const double h = 0.25;  // the example's cells are 0.25 m square
  const auto rows = [h](const Vec3& x) { return std::lround(x.y() / h) % 2 == 0 ? 1.0 : -1.0; };
  const auto constant = [](const Vec3&) { return 1.0; };
  const double unseen = pressure_energy(0.0, rows);
  const double resisted = pressure_energy(0.2, rows);
  EXPECT_LT(std::abs(unseen), 1e-9 * resisted);
  EXPECT_GT(resisted, 0.0);
  EXPECT_NEAR(pressure_energy(0.2, constant), pressure_energy(0.0, constant),
              1e-9 * std::abs(pressure_energy(0.0, constant)));
}

// Springs at the nodes the points barely support (docs/theory.md eq. 6.2). The oedometer block
// fills 4 x 4 square cells of 0.25 m, with a buffer row of empty cells above it. One point of the
// block's top row is moved just into the buffer row (y = 1.01 m), so that two nodes on top of it
// see a little of it (support fill 0.015 < 0.05: a spring of 0.7 of the full one); the other
// nodes on top see no point (fill 0) and get E_s |c| / (4 h^2) = E_s / 4 from each of their
// active cells, on each displacement component; the block's surface nodes (fill about 1/2) and
// inner nodes (fill 1) get none; and the springs act on the step's displacement, so the internal
// force changes by exactly the added stiffness times it.
TEST(GridSystemSparseNodes, OnlyTheNodesThePointsBarelyReachGetTheSpring) {
  const auto spec = testing::read_example("oedometer/oedometer.yaml");
  auto model = build_model(spec);
  auto& pts = model->points;
  Index moved = -1;
  for (Index p = 0; p < pts.size(); ++p)
    if (std::abs(pts.position[p].x() - 0.3125) < 1e-9 &&
        std::abs(pts.position[p].y() - 0.9375) < 1e-9)
      moved = p;
  ASSERT_GE(moved, 0);
  const auto where = model->locator->locate(Vec3(0.3125, 1.01, 0.0), pts.cell[moved]);
  ASSERT_TRUE(where);
  pts.position[moved] = Vec3(0.3125, 1.01, 0.0);
  pts.cell[moved] = where->cell;
  pts.local[moved] = where->xi;
  const double modulus = 100.0;
  Vector du;
  const auto assemble = [&](double sparse, Vector& f, SparseMatrix& K,
                            std::vector<Index>& free_index, std::vector<Index>& nodes,
                            std::vector<Index>& cells) {
    GridSettings settings;
    settings.kinematics = spec.kinematics;
    settings.sparse_node_modulus = sparse;
    testing::GridHarness grid(model->mesh, model->topology, model->material_pointers(), settings);
    MaterialPoints points = model->points;
    grid.initialise(points);
    grid.set_constraints(std::vector<char>(grid.num_dofs(), 0));
    if (du.size() == 0) {
      du = Vector::Zero(grid.num_dofs());
      for (Index d = 0; d < du.size(); ++d) du(d) = 1e-3 * std::sin(0.7 * d + 0.3);
    }
    EXPECT_TRUE(grid.internal_force(points, du, f, &K));
    free_index = grid.free_index();
    nodes = grid.active_nodes();
    cells = grid.active_cells();
  };
  Vector f_off, f_on;
  SparseMatrix K_off, K_on;
  std::vector<Index> free_off, free_on, nodes, cells, cells_on;
  assemble(0.0, f_off, K_off, free_off, nodes, cells);
  assemble(modulus, f_on, K_on, free_on, nodes, cells_on);
  ASSERT_EQ(free_off, free_on);
  ASSERT_EQ(cells, cells_on);
  const SparseMatrix added = K_on - K_off;
  // Expected, from eq. 6.2 on this uniform grid (h = 0.25 m, the bilinear hats): for a node on
  // top of the buffer row (y = 1.25 m), with c_a of its cells active, fill s = sum_p N_a v_p /
  // (c_a h^2 / 4) and a spring E_s (1 - s / 0.05) c_a / 4.
  const double h = 0.25;
  std::map<Index, int> active_cells_of;
  for (const Index c : cells)
    for (const Index n : model->mesh.cell_nodes(c))
      if (model->mesh.nodes[n].y() > 1.25 - 1e-9) ++active_cells_of[n];
  ASSERT_EQ(active_cells_of.size(), 5u);  // the 5 nodes of the top row
  std::map<Index, double> expected;
  int partly = 0;
  for (const auto& [n, count] : active_cells_of) {
    double seen = 0.0;
    for (Index p = 0; p < pts.size(); ++p) {
      const Vec3 d = (pts.position[p] - model->mesh.nodes[n]).cwiseAbs() / h;
      seen += std::max(0.0, 1.0 - d.x()) * std::max(0.0, 1.0 - d.y()) * pts.volume[p];
    }
    const double fill = seen / (count * h * h / 4.0);
    if (fill > 0.0) ++partly;
    expected[n] = modulus * (1.0 - fill / 0.05) * count / 4.0;
  }
  EXPECT_EQ(partly, 2);  // the two nodes above the moved point's cell
  const int dim = 2;
  for (std::size_t a = 0; a < nodes.size(); ++a)
    for (int i = 0; i < dim; ++i) {
      const Index row = free_on[a * dim + i];
      const auto it = expected.find(nodes[a]);
      EXPECT_NEAR(added.coeff(row, row), it == expected.end() ? 0.0 : it->second, 1e-9 * modulus)
          << "node " << nodes[a] << " at y = " << model->mesh.nodes[nodes[a]].y();
    }
  // Nothing off the diagonal, and the force is the added stiffness on the step's displacement.
  double off_diagonal = 0.0;
  for (int k = 0; k < added.outerSize(); ++k)
    for (SparseMatrix::InnerIterator it(added, k); it; ++it)
      if (it.row() != it.col()) off_diagonal = std::max(off_diagonal, std::abs(it.value()));
  EXPECT_EQ(off_diagonal, 0.0);
  Vector du_free = Vector::Zero(K_on.cols()), df_free = Vector::Zero(K_on.rows());
  for (Index d = 0; d < static_cast<Index>(free_on.size()); ++d)
    if (free_on[d] >= 0) {
      du_free(free_on[d]) = du(d);
      df_free(free_on[d]) = f_on(d) - f_off(d);
    }
  const Vector spring_force = added * du_free;
  ASSERT_GT(spring_force.norm(), 0.0);
  EXPECT_LT((df_free - spring_force).norm(), 1e-12 * spring_force.norm());
}

// The ghost penalty in the system (eq. 6.3): on the oedometer, whose top row of cells is the
// body's edge (the buffer row above it is empty), it adds a force linear in the step's
// displacement, and none for a translation or a uniform strain of the whole grid, which a
// node spring (eq. 6.2) would resist; a fill limit below that row's fill removes it.
TEST(GridSystemGhostPenalty, AddsALinearForceThatLinearFieldsDoNotFeel) {
  const auto spec = testing::read_example("oedometer/oedometer.yaml");
  auto model = build_model(spec);
  const auto force = [&](double gamma, const std::function<double(const Vec3&, int)>& field,
                         double scale, double fill_limit = 1.0) {
    GridSettings settings;
    settings.kinematics = spec.kinematics;
    settings.ghost_penalty = gamma;
    settings.ghost_penalty_fill = fill_limit;  // the top row is full: 1 lets it carry the penalty
    testing::GridHarness grid(model->mesh, model->topology, model->material_pointers(), settings);
    MaterialPoints points = model->points;
    grid.initialise(points);
    grid.set_constraints(std::vector<char>(grid.num_dofs(), 0));
    Vector du(grid.num_dofs()), f;
    for (std::size_t a = 0; a < grid.active_nodes().size(); ++a)
      for (int i = 0; i < 2; ++i)
        du(a * 2 + i) = scale * field(model->mesh.nodes[grid.active_nodes()[a]], i);
    EXPECT_TRUE(grid.internal_force(points, du, f, nullptr));
    return f;
  };
  const auto bending = [](const Vec3& x, int i) {
    return i == 0 ? 1e-3 * std::sin(3.0 * x.y() + 1.0) * x.x() : 2e-3 * x.x() * x.x();
  };
  const auto linear = [](const Vec3& x, int i) {
    return i == 0 ? 1e-3 + 2e-3 * x.x() - 1e-3 * x.y() : -5e-4 + 1e-3 * x.x() + 3e-3 * x.y();
  };
  const double gamma = 0.05;
  const Vector ghost = force(gamma, bending, 1.0) - force(0.0, bending, 1.0);
  ASSERT_GT(ghost.norm(), 1e-6 * force(0.0, bending, 1.0).norm());
  const Vector doubled = force(gamma, bending, 2.0) - force(0.0, bending, 2.0);
  EXPECT_LT((doubled - 2.0 * ghost).norm(), 1e-9 * ghost.norm());
  const Vector along_linear = force(gamma, linear, 1.0) - force(0.0, linear, 1.0);
  EXPECT_LT(along_linear.norm(), 1e-9 * ghost.norm());
  // Under a fill limit below the top row's fill (full) no cell is an edge cell: no force.
  const Vector limited = force(gamma, bending, 1.0, 0.999) - force(0.0, bending, 1.0);
  EXPECT_EQ(limited.norm(), 0.0);
}

// The exact projection of each cell type: its null space is the constant pressures, and on a
// Quad4 cell it is the closed form (1/36) [4 2 1 2; 2 4 2 1; 1 2 4 2; 2 1 2 4] - 1/16.
TEST(GridSystemPressureStabilisation, TheExactProjectionKeepsOnlyConstants) {
  const auto check = [](const auto& projection) {
    const Eigen::MatrixXd p = projection;
    const Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eigen(p);
    EXPECT_LT((p * Eigen::VectorXd::Ones(p.rows())).norm(), 1e-14);
    EXPECT_NEAR(eigen.eigenvalues()(0), 0.0, 1e-14);
    EXPECT_GT(eigen.eigenvalues()(1), 1e-3);  // every non-constant pressure is penalised
  };
  check(exact_pressure_projection<Element<CellType::Tri3>>());
  check(exact_pressure_projection<Element<CellType::Quad4>>());
  check(exact_pressure_projection<Element<CellType::Tet4>>());
  check(exact_pressure_projection<Element<CellType::Hex8>>());
  Eigen::Matrix4d quad;
  quad << 4, 2, 1, 2, 2, 4, 2, 1, 1, 2, 4, 2, 2, 1, 2, 4;
  quad = quad / 36.0 - Eigen::Matrix4d::Constant(1.0 / 16.0);
  EXPECT_LT((exact_pressure_projection<Element<CellType::Quad4>>() - quad).norm(), 1e-14);
}

// DDMP gradients and GIMP weights reproduce a linear displacement field exactly: a uniform
// strain increment gives the same stress at every point, as with standard MPM, and convect
// moves every point with the field.
void check_linear_field(GridInterpolation interpolation) {
  auto spec = testing::read_example("oedometer/oedometer.yaml");
  auto model = build_model(spec);
  if (interpolation == GridInterpolation::Gimp) scatter_points(*model, 0.6);
  GridSettings settings;
  settings.kinematics = spec.kinematics;
  settings.interpolation = interpolation;
  testing::GridHarness grid(model->mesh, model->topology, model->material_pointers(), settings);
  grid.initialise(model->points);
  grid.set_constraints(std::vector<char>(grid.num_dofs(), 0));
  Vector du(grid.num_dofs());
  auto field = [](const Vec3& x) {
    return Vec3(0.002 * x.x() + 0.001 * x.y() + 1e-3, -0.003 * x.y() - 2e-3, 0.0);
  };
  for (Index a = 0; a < static_cast<Index>(grid.active_nodes().size()); ++a) {
    const Vec3 u = field(model->mesh.nodes[grid.active_nodes()[a]]);
    du(2 * a) = u.x();
    du(2 * a + 1) = u.y();
  }
  MaterialPoints updated = model->points;
  ASSERT_TRUE(grid.commit_state(updated, du));
  const Mat3 first = updated.stress.front();
  for (const Mat3& s : updated.stress) EXPECT_LT((s - first).norm(), 1e-9 * first.norm());
  EXPECT_GT(first.norm(), 1.0);

  const std::vector<Vec3> before = model->points.position;
  grid.convect(model->points, du, du, Vector::Zero(du.size()), 1.0, false);
  for (Index p = 0; p < model->points.size(); ++p)
    EXPECT_LT((model->points.position[p] - before[p] - field(before[p])).norm(), 1e-14);
}

TEST(GridSystemDualDomain, LinearFieldGivesUniformStress) {
  check_linear_field(GridInterpolation::DualDomain);
}
TEST(GridSystemGimp, LinearFieldGivesUniformStress) { check_linear_field(GridInterpolation::Gimp); }

// GIMP maps mass, momentum and gravity through the wide stencil: nothing is lost, and a node
// outside a point's cell gets its share.
TEST(GridSystemGimp, MapsMassAndLoadsThroughTheStencil) {
  auto spec = testing::read_example("column/column.yaml");
  auto model = build_model(spec);
  scatter_points(*model, 0.6);
  for (Index p = 0; p < model->points.size(); ++p) model->points.velocity[p] = Vec3(0.0, 2.0, 0.0);
  GridSettings settings;
  settings.kinematics = spec.kinematics;
  settings.interpolation = GridInterpolation::Gimp;
  testing::GridHarness grid(model->mesh, model->topology, model->material_pointers(), settings);
  grid.initialise(model->points);
  double mass = 0.0;
  for (Index p = 0; p < model->points.size(); ++p) mass += model->points.mass[p];
  const Vector& m = grid.mass();
  double mx = 0.0, my = 0.0, momentum = 0.0;
  for (Index d = 0; d < m.size(); d += 2) {
    mx += m(d);
    my += m(d + 1);
    momentum += m(d + 1) * grid.velocity()(d + 1);
  }
  EXPECT_NEAR(mx, mass, 1e-12 * mass);
  EXPECT_NEAR(my, mass, 1e-12 * mass);
  EXPECT_NEAR(momentum, 2.0 * mass, 1e-12 * mass);
  const Vector f = grid.external_force(model->points, Vec3(0.0, -10.0, 0.0), {});
  double fy = 0.0;
  for (Index d = 1; d < f.size(); d += 2) fy += f(d);
  EXPECT_NEAR(fy, -10.0 * mass, 1e-12 * mass);
  // Nodes with mass lie in more cells than the points occupy: the stencils reach past the cells.
  int nodes_with_mass = 0;
  for (Index d = 0; d < m.size(); d += 2) nodes_with_mass += m(d) > 0.0;
  std::vector<char> occupied(model->mesh.num_cells(), 0);
  for (Index c : model->points.cell) occupied[c] = 1;
  std::vector<char> node_of_occupied(model->mesh.num_nodes(), 0);
  for (Index c = 0; c < model->mesh.num_cells(); ++c)
    if (occupied[c])
      for (Index n : model->mesh.cell_nodes(c)) node_of_occupied[n] = 1;
  int count = 0;
  for (char flag : node_of_occupied) count += flag;
  EXPECT_GT(nodes_with_mass, count);
}

// GIMP on a mesh that is not a rectilinear grid is refused with the reason.
TEST(GridSystemGimp, RefusesAMeshThatIsNotARectilinearGrid) {
  auto spec = testing::read_example("column/column.yaml");
  spec.mesh.generate->cell_type = CellType::Tri3;
  spec.numerics.interpolation = spec::Interpolation::Standard;  // else build_model refuses it
  auto model = build_model(spec);
  GridSettings settings;
  settings.interpolation = GridInterpolation::Gimp;
  try {
    testing::GridHarness grid(model->mesh, model->topology, model->material_pointers(), settings);
    ADD_FAILURE() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("numerics.interpolation: gimp needs a rectilinear grid"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace geompm
