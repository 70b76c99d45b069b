// Initial stresses given directly (docs/user-guide.md, "initial_stress"). A weightless Tresca
// block starts from an isotropic 66 kPa, the start of a cone-penetration benchmark, held by rollers
// at its sides and base and by a 66 kPa surcharge on its top (a surface load, docs/theory.md §16):
// the start is in balance, so a step changes no stress (to Newton's tolerance), and every point
// started from exactly the stress given. A stress that varies with depth is given as expressions.
// (In plane strain: in axisymmetry the points' quadrature of the hoop term is not exact, sub-cell
// centres weighing r N_a, quadratic in r, by the midpoint rule, so a uniform stress is not quite in
// balance at the nodes near the axis; docs/validation.md.)
// A deviator beyond 2 s_u is outside the Tresca surface, and the model is refused with the point
// and the stress, as the K0 procedure refuses its stresses; a body also set by the K0 procedure
// too.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "geompm/io/model_reader.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

std::string cone_start(const std::string& stress, const std::string& extra_phase_keys = "") {
  return R"(title: Isotropic initial stress
analysis: {kinematics: plane_strain}
mesh:
  generate: {cell: quad4, origin: [0, 0], x: {length: 2, cells: 4}, y: {length: 2.5, cells: 5}}
materials:
  clay: {model: tresca, su: 20, E: 6000, nu: 0.49, density: 0}
bodies:
  soil:
    material: clay
    region: {box: {min: [0, 0], max: [2, 2]}}
    initial_stress: )" +
         stress + R"(
phases:
  - name: hold
    duration: 1
    time_step: 1
    newton: {residual_tolerance: 1.0e-12, displacement_tolerance: 1.0e-12}
    surface_loads:
      - {pressure: 66}
)" + extra_phase_keys +
         R"(    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
output:
  vtk: {every: 0}
)";
}

TEST(InitialStress, IsotropicStartUnderItsSurchargeIsInBalance) {
  const spec::Model spec =
      read_model_from_string(cone_start("{sxx: -66, syy: -66, szz: -66}"), "cone.yaml");
  const auto model = build_model(spec);
  for (Index p = 0; p < model->points.size(); ++p)
    EXPECT_EQ(model->points.stress[p], -66.0 * Mat3::Identity());
  const auto run = testing::run_spec(spec, "initial_stress_isotropic");
  ASSERT_EQ(run.summary.steps, 1);
  const MaterialPoints& points = run.model->points;
  double worst = 0.0;
  for (Index p = 0; p < points.size(); ++p)
    worst = std::max(worst, (points.stress[p] + 66.0 * Mat3::Identity()).norm());
  EXPECT_LT(worst, 1e-8 * 66.0);
}

TEST(InitialStress, VariesWithDepthAsExpressions) {
  const auto model = build_model(read_model_from_string(
      cone_start("{sxx: \"-30 - 5*(2 - y)\", syy: \"-40 - 10*(2 - y)\", szz: \"-30 - 5*(2 - y)\", "
                 "sxy: \"0.5*x\"}"),
      "depth.yaml"));
  const MaterialPoints& points = model->points;
  for (Index p = 0; p < points.size(); ++p) {
    const double depth = 2.0 - points.position[p].y();
    Mat3 expected = Mat3::Zero();
    expected.diagonal() = Vec3(-30 - 5 * depth, -40 - 10 * depth, -30 - 5 * depth);
    expected(0, 1) = expected(1, 0) = 0.5 * points.position[p].x();
    EXPECT_NEAR((points.stress[p] - expected).norm(), 0.0, 1e-12);
    // Stored as the elastic strain that gives it: the material's update returns it.
    StressUpdate check;
    const Mat3 strain = 0.5 * symmetric_log(points.elastic_left_cauchy_green[p]);
    model->materials[points.material[p]]->update(strain, points.internal[p], check);
    EXPECT_NEAR((check.kirchhoff - expected).norm(), 0.0, 1e-9);
  }
}

TEST(InitialStress, OutsideTheYieldSurfaceIsRefused) {
  // |syy - sxx| = 50 > 2 s_u = 40.
  const std::string message = testing::build_error(cone_start("{sxx: -40, syy: -90, szz: -40}"));
  EXPECT_NE(message.find("model.yaml:11: bodies.soil.initial_stress: the initial stress of the "
                         "point at"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("lies outside the yield surface of 'tresca'"), std::string::npos);
}

TEST(InitialStress, ABodyAlsoSetByTheK0ProcedureIsRefused) {
  const std::string message =
      testing::build_error(cone_start("{sxx: -66, syy: -66, szz: -66}",
                                      "    gravity: {acceleration: [0, -10]}\n"
                                      "    k0_procedure: {K0: 1}\n"));
  EXPECT_NE(message.find("bodies.soil.initial_stress: the body 'soil' is also set by the K0 "
                         "procedure"),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace geompm
