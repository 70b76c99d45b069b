// The step's unknowns and equations (docs/architecture.md, "Unknowns" and "Contributions"): the
// DofMap numbers fields block by block and knows what each unknown is; the sparsity builder holds
// exactly the couplings declared, also of a field that is not nodal (a rigid body's unknown); and
// a contribution added to a step system enters its residual and tangent and nothing else - the
// recipe for adding a term, on a toy one.
#include <gtest/gtest.h>

#include <Eigen/Dense>

#include "geompm/dofs/dof_map.hpp"
#include "geompm/dofs/sparsity.hpp"
#include "geompm/physics/contribution.hpp"
#include "grid_harness.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

TEST(DofMap, NumbersFieldsBlockByBlockAndNamesEachUnknown) {
  DofMap dofs({10, 11, 12});  // three active nodes, mesh nodes 10..12
  const int u = dofs.add_nodal_field("displacement", FieldKind::Displacement, 2);
  const int p = dofs.add_nodal_field("pressure", FieldKind::Pressure, 1);
  const int body = dofs.add_field("rigid body", FieldKind::Other, 1, 3);
  EXPECT_EQ(dofs.size(), 3 * 2 + 3 + 3);
  EXPECT_EQ(dofs.dof(u, 2, 1), 5);
  EXPECT_EQ(dofs.dof(p, 1), 7);
  EXPECT_EQ(dofs.dof(body, 0, 2), 11);
  const Unknown seven = dofs.unknown(7);
  EXPECT_EQ(seven.field, p);
  EXPECT_EQ(seven.entity, 1);
  EXPECT_EQ(dofs.active_nodes()[seven.entity], 11);
  EXPECT_EQ(dofs.unknown(3).component, 1);
  EXPECT_EQ(dofs.find("pressure"), p);
  EXPECT_EQ(dofs.find("contact"), -1);
  EXPECT_THROW(dofs.add_nodal_field("pressure", FieldKind::Pressure, 1), std::logic_error);

  // Constraints: a later value wins; the free unknowns keep their order.
  dofs.constrain(dofs.dof(u, 0, 1), 0.5);
  dofs.constrain(dofs.dof(u, 0, 1), 0.25);
  dofs.number_free();
  EXPECT_EQ(dofs.num_free(), dofs.size() - 1);
  EXPECT_EQ(dofs.free_index(1), -1);
  EXPECT_EQ(dofs.free_index(2), 1);
  EXPECT_EQ(dofs.dof_of_free(1), 2);
  Vector x = Vector::LinSpaced(dofs.num_free(), 1.0, double(dofs.num_free())), all, back;
  dofs.expand(x, all);
  EXPECT_EQ(all(1), 0.25);
  EXPECT_EQ(all(2), 2.0);
  dofs.restrict_to_free(all, back);
  EXPECT_EQ(back, x);
}

TEST(SparsityBuilder, HoldsTheDeclaredCouplingsOfNodalAndOtherFields) {
  DofMap dofs({0, 1, 2});
  const int u = dofs.add_nodal_field("displacement", FieldKind::Displacement, 2);
  const int body = dofs.add_field("rigid body", FieldKind::Other, 1, 1);
  dofs.constrain(dofs.dof(u, 2, 0));
  dofs.number_free();
  SparsityBuilder builder(dofs);
  builder.couple_nodes(std::vector<Index>{0, 1});
  const std::vector<Index> tie = {dofs.dof(body, 0), dofs.dof(u, 2, 1)};
  builder.couple_unknowns(tie);
  const SparseMatrix pattern = builder.build();
  Eigen::MatrixXi expected = Eigen::MatrixXi::Zero(dofs.num_free(), dofs.num_free());
  for (int a : {0, 1, 2, 3})
    for (int b : {0, 1, 2, 3}) expected(a, b) = 1;
  for (Index a : tie)
    for (Index b : tie) expected(dofs.free_index(a), dofs.free_index(b)) = 1;
  Eigen::MatrixXi got = Eigen::MatrixXi::Zero(dofs.num_free(), dofs.num_free());
  for (Index j = 0; j < pattern.outerSize(); ++j)
    for (SparseMatrix::InnerIterator it(pattern, j); it; ++it) got(it.row(), it.col()) = 1;
  EXPECT_EQ(got, expected);
  // Rows ascend in every column (the assembly's lower_bound relies on it).
  for (Index j = 0; j < pattern.cols(); ++j)
    for (int at = pattern.outerIndexPtr()[j] + 1; at < pattern.outerIndexPtr()[j + 1]; ++at)
      EXPECT_LT(pattern.innerIndexPtr()[at - 1], pattern.innerIndexPtr()[at]);
  SparseMatrix tangent = pattern;
  add_to_tangent(tangent, dofs, dofs.dof(body, 0), dofs.dof(u, 2, 1), 2.0);
  EXPECT_EQ(tangent.coeff(dofs.free_index(dofs.dof(body, 0)), dofs.free_index(dofs.dof(u, 2, 1))),
            2.0);
  // A constrained unknown takes nothing; an undeclared coupling is an error.
  add_to_tangent(tangent, dofs, dofs.dof(u, 2, 0), dofs.dof(u, 0, 0), 1.0);
  EXPECT_THROW(add_to_tangent(tangent, dofs, dofs.dof(body, 0), dofs.dof(u, 0, 0), 1.0),
               std::logic_error);
}

// The recipe's toy term: a spring k on the x displacement of one node towards `target`.
class NodeSpring final : public Contribution {
 public:
  NodeSpring(const DofMap& dofs, Index node, double k, double target)
      : dofs_(dofs), node_(node), k_(k), target_(target) {}
  const char* name() const override { return "node spring"; }
  bool add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) override {
    const Index d = dofs_.dof(dofs_.find("displacement"), node_, 0);
    forces.internal(d) += k_ * (du(d) - target_);
    if (tangent) add_to_tangent(*tangent, dofs_, d, d, k_);
    return true;
  }

 private:
  const DofMap& dofs_;
  Index node_;
  double k_, target_;
};

TEST(StepSystem, AContributionAddsItsForceAndStiffnessAndNothingElse) {
  auto spec = testing::read_example("oedometer/oedometer.yaml");
  auto model = build_model(spec);
  GridSettings settings;
  settings.kinematics = spec.kinematics;
  testing::GridHarness plain(model->mesh, model->topology, model->material_pointers(), settings);
  testing::GridHarness sprung(model->mesh, model->topology, model->material_pointers(), settings);
  MaterialPoints a = model->points, b = model->points;
  plain.initialise(a);
  sprung.initialise(b);
  const double k = 123.0, target = 1e-3;
  sprung.system().add(std::make_unique<NodeSpring>(sprung.system().dofs(), 3, k, target));
  plain.set_constraints(std::vector<char>(plain.num_dofs(), 0));
  sprung.set_constraints(std::vector<char>(sprung.num_dofs(), 0));
  // A non-uniform increment, so that the soil resists it too.
  Vector du = 2e-4 * Vector::LinSpaced(plain.num_dofs(), -1.0, 1.0), f_plain, f_sprung;
  SparseMatrix K_plain, K_sprung;
  ASSERT_TRUE(plain.internal_force(a, du, f_plain, &K_plain));
  ASSERT_TRUE(sprung.internal_force(b, du, f_sprung, &K_sprung));
  const Index d = sprung.system().dofs().dof(0, 3, 0);
  Vector expected = f_plain;
  expected(d) += k * (du(d) - target);
  ASSERT_GT(f_plain.norm(), 0.0);
  EXPECT_LT((f_sprung - expected).norm(), 1e-12 * f_plain.norm());
  const Eigen::MatrixXd difference = Eigen::MatrixXd(K_sprung) - Eigen::MatrixXd(K_plain);
  EXPECT_NEAR(difference(d, d), k, 1e-9 * k);
  EXPECT_NEAR(difference.norm(), k, 1e-9 * k);
}

}  // namespace
}  // namespace geompm
