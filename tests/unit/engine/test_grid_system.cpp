// The assembled tangent of the grid system against a finite difference of its internal force,
// for standard MPM and DDMP gradients, in plane strain and axisymmetry, with points spread over
// several cells, in the displacement and the mixed p-u formulation (docs/theory.md eqs. 3.9,
// 6.1, 8.2, 9.3-9.7).
#include <gtest/gtest.h>

#include <map>
#include <random>

#include "geompm/physics/grid_system.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

// A material for every point of the example, in the mixed formulation when `mixed`.
struct MaterialChoice {
  std::string model;
  std::map<std::string, double> parameters;
  bool mixed = false;
};

void check_assembled_tangent(const std::string& example, bool dual_domain,
                             const MaterialChoice* choice = nullptr) {
  auto spec = testing::read_example(example);
  if (choice)
    for (auto& material : spec.materials) {
      material.model = choice->model;
      material.parameters = choice->parameters;
    }
  auto model = build_model(spec);
  GridSettings settings;
  settings.kinematics = spec.kinematics;
  settings.empty_cell_modulus = 1e-3 * model->largest_modulus();
  settings.dual_domain = dual_domain;
  if (choice) settings.mixed.assign(spec.materials.size(), choice->mixed);
  GridSystem grid(model->mesh, model->topology, model->material_pointers(), settings);
  grid.initialise(model->points);
  grid.set_constraints(std::vector<char>(grid.num_dofs(), 0));

  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  Vector du(grid.num_dofs());
  for (Index d = 0; d < du.size(); ++d) du(d) = 1e-3 * u(rng);
  Vector f;
  SparseMatrix K;
  ASSERT_TRUE(grid.internal_force(model->points, du, f, &K));
  const Eigen::MatrixXd dense = Eigen::MatrixXd(K);

  const double h = 1e-7;
  double worst = 0.0;
  for (Index j = 0; j < du.size(); j += 3) {  // every third column keeps the test fast
    Vector plus = du, minus = du, fp, fm;
    plus(j) += h;
    minus(j) -= h;
    ASSERT_TRUE(grid.internal_force(model->points, plus, fp, nullptr));
    ASSERT_TRUE(grid.internal_force(model->points, minus, fm, nullptr));
    const Vector column = (fp - fm) / (2 * h);
    worst = std::max(
        worst, (dense.col(grid.free_index()[j]) - column).norm() / std::max(column.norm(), 1e-12));
  }
  EXPECT_LT(worst, 1e-5) << example << (dual_domain ? " (DDMP)" : " (standard)")
                         << (choice ? " " + choice->model : "");
}

// Plastic flow and a non-zero pressure field in the mixed formulation: random increments of the
// scaled pressure unknowns as large as the displacements give pressures of the order of the
// stresses, so every block of eqs. 9.3-9.4 and the stabilisation (9.5) is exercised.
const MaterialChoice mixed_tresca{
    "tresca", {{"su", 5.0}, {"E", 1e4}, {"nu", 0.49}, {"density", 1.0}}, true};
const MaterialChoice mixed_mohr_coulomb{
    "mohr_coulomb",
    {{"c", 2.0}, {"phi", 30.0}, {"psi", 10.0}, {"E", 1e4}, {"nu", 0.3}, {"density", 1.0}},
    true};

TEST(GridSystemTangent, MixedTrescaPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", false, &mixed_tresca);
}
TEST(GridSystemTangent, MixedMohrCoulombPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", false, &mixed_mohr_coulomb);
}
TEST(GridSystemTangent, MixedTrescaAxisymmetric) {
  check_assembled_tangent("column/column_axisymmetric.yaml", false, &mixed_tresca);
}
TEST(GridSystemTangent, MixedTrescaDualDomain) {
  check_assembled_tangent("oedometer/oedometer.yaml", true, &mixed_tresca);
}
TEST(GridSystemTangent, MixedMohrCoulomb3D) {
  check_assembled_tangent("column/column_3d.yaml", false, &mixed_mohr_coulomb);
}

TEST(GridSystemTangent, StandardPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", false);
}
TEST(GridSystemTangent, DualDomainPlaneStrain) {
  check_assembled_tangent("oedometer/oedometer.yaml", true);
}
TEST(GridSystemTangent, DualDomainAxisymmetric) {
  check_assembled_tangent("column/column_axisymmetric.yaml", true);
}

// DDMP gradients reproduce a linear displacement field exactly: a uniform strain increment
// gives the same stress at every point, as with standard MPM.
TEST(GridSystemDualDomain, LinearFieldGivesUniformStress) {
  auto spec = testing::read_example("oedometer/oedometer.yaml");
  auto model = build_model(spec);
  GridSettings settings;
  settings.kinematics = spec.kinematics;
  settings.dual_domain = true;
  GridSystem grid(model->mesh, model->topology, model->material_pointers(), settings);
  grid.initialise(model->points);
  grid.set_constraints(std::vector<char>(grid.num_dofs(), 0));
  Vector du(grid.num_dofs());
  for (Index a = 0; a < static_cast<Index>(grid.active_nodes().size()); ++a) {
    const Vec3& x = model->mesh.nodes[grid.active_nodes()[a]];
    du(2 * a) = 0.002 * x.x() + 0.001 * x.y();
    du(2 * a + 1) = -0.003 * x.y();
  }
  Vector f;
  ASSERT_TRUE(grid.internal_force(model->points, du, f, nullptr));
  const Mat3 first = grid.trial().stress.front();
  for (const Mat3& s : grid.trial().stress) EXPECT_LT((s - first).norm(), 1e-9 * first.norm());
  EXPECT_GT(first.norm(), 1.0);
}

}  // namespace
}  // namespace geompm
