// Initial stresses of layered level ground (docs/theory.md §10): the K0 procedure followed by
// gravity stays in equilibrium with sigma_v = the weight of the layers above and
// sigma_h = K0 sigma_v per layer; a ramped gravity phase (gravity loading) gives
// sigma_h = nu / (1 - nu) sigma_v (1D compression); what the K0 procedure cannot represent is
// refused when the model is built.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "geompm/analysis/geostatic_stress.hpp"
#include "run_model.hpp"

namespace geompm {
namespace {

constexpr double g = 10.0;
// Two layers: clay (density 2.0, K0 0.7, nu 0.4) below y = 4, sand (1.8, K0 0.5, nu 0.3) up to
// the surface at y = 10. Unit weights 20 and 18 kN/m3.
constexpr double surface = 10.0, interface = 4.0;
constexpr double sand_density = 1.8, clay_density = 2.0;

double vertical_stress(double y) {
  if (y >= interface) return -g * sand_density * (surface - y);
  return -g * (sand_density * (surface - interface) + clay_density * (interface - y));
}

const std::string kMaterials = R"m(materials:
  sand: {model: linear_elastic, E: 20000, nu: 0.3, density: 1.8}
  clay: {model: linear_elastic, E: 10000, nu: 0.4, density: 2.0}
)m";

// {bodies}: the layering; {phase}: the first phase's loading keys.
std::string plane_strain_model(const std::string& bodies, const std::string& phase) {
  return fmt::format(R"m(analysis: {{kinematics: plane_strain}}
mesh: {{generate: {{x: {{length: 2, cells: 2}}, y: {{length: 12, cells: 12}}}}}}
{}bodies:
{}phases:
  - name: geostatic
    duration: 1.0
    time_step: {{initial: 0.05, max: 1.0}}
    newton: {{residual_tolerance: 1.0e-10}}
{}    fixities:
      - {{boundary: left, fix: normal}}
      - {{boundary: right, fix: normal}}
      - {{boundary: bottom, fix: all}}
output:
  vtk: {{every: 0}}
  history:
    - {{quantity: reaction, boundary: bottom, component: y, name: base}}
)m",
                     kMaterials, bodies, phase);
}

const std::string kTwoBodies =
    R"m(  sand_layer: {material: sand, region: {box: {min: [0, 4], max: [2, 10]}}}
  clay_layer: {material: clay, region: {box: {min: [0, 0], max: [2, 4]}}}
)m";
const std::string kLayeredBody = R"m(  ground:
    region: {box: {min: [0, 0], max: [2, 10]}}
    layers: [{material: sand, bottom: 4}, {material: clay}]
)m";
const std::string kK0Phase = R"m(    k0_procedure: {K0: {sand: 0.5, clay: 0.7}}
    gravity: {acceleration: [0, -10]}
)m";

struct Errors {
  double displacement = 0, vertical = 0, ratio = 0;
};

// Largest displacement (relative to the settlement scale rho g H^2 / E), vertical stress error
// (relative to the stress at the base) and error of sigma_h / sigma_v against `ratio(material)`.
template <class Ratio>
Errors geostatic_errors(const Model& model, Ratio ratio) {
  const auto& p = model.points;
  const int v = model.mesh.dim() - 1;
  const double base = std::abs(vertical_stress(0.0));
  Errors e;
  for (Index i = 0; i < p.size(); ++i) {
    e.displacement = std::max(e.displacement, p.displacement[i].norm() / (base * 10.0 / 1.0e4));
    const Mat3& s = p.stress[i];
    e.vertical =
        std::max(e.vertical, std::abs(s(v, v) - vertical_stress(p.initial_position[i](v))) / base);
    const double K = ratio(model.spec.materials[p.material[i]].name);
    for (int h = 0; h < 3; ++h)
      if (h != v) e.ratio = std::max(e.ratio, std::abs(s(h, h) / s(v, v) - K));
  }
  return e;
}

double k0_of(const std::string& material) { return material == "sand" ? 0.5 : 0.7; }

class K0Procedure : public ::testing::TestWithParam<std::string> {};

// The K0 stresses are in equilibrium with gravity: switching gravity on moves nothing.
TEST_P(K0Procedure, FollowedByGravityStaysInEquilibrium) {
  const std::string bodies = GetParam() == "two_bodies" ? kTwoBodies : kLayeredBody;
  const auto spec = read_model_from_string(plane_strain_model(bodies, kK0Phase), "k0.yaml");
  const auto built = build_model(spec);
  // Before any step: the geostatic state itself.
  const Errors initial = geostatic_errors(*built, k0_of);
  EXPECT_LT(initial.vertical, 1e-12);
  EXPECT_LT(initial.ratio, 1e-12);

  const auto run = testing::run_spec(spec, "k0_" + GetParam());
  const Errors e = geostatic_errors(*run.model, k0_of);
  std::printf("[K0 then gravity, %s] displacement %.2e, sigma_v error %.2e, K0 error %.2e\n",
              GetParam().c_str(), e.displacement, e.vertical, e.ratio);
  EXPECT_LT(e.displacement, 1e-9);
  EXPECT_LT(e.vertical, 1e-9);
  EXPECT_LT(e.ratio, 1e-9);
  // The base carries the weight of both layers (2 m wide).
  const double weight = 2.0 * g * (sand_density * 6.0 + clay_density * 4.0);
  EXPECT_NEAR(run.column("base").back(), weight, 1e-9 * weight);
  EXPECT_LE(run.summary.max_iterations_in_a_step, 1);
}

INSTANTIATE_TEST_SUITE_P(Layering, K0Procedure, ::testing::Values("two_bodies", "layered_body"));

TEST(K0Procedure, ThreeDimensionalLayeredGround) {
  const std::string text = fmt::format(R"m(analysis: {{kinematics: 3d}}
mesh: {{generate: {{x: {{length: 1, cells: 1}}, y: {{length: 1, cells: 1}},
                  z: {{length: 11, cells: 11}}}}}}
{}bodies:
  ground:
    region: {{box: {{min: [0, 0, 0], max: [1, 1, 10]}}}}
    layers: [{{material: sand, bottom: 4}}, {{material: clay}}]
phases:
  - name: geostatic
    time_step: 1.0
    k0_procedure: {{K0: {{sand: 0.5, clay: 0.7}}}}
    gravity: {{acceleration: [0, 0, -10]}}
    fixities:
      - {{boundary: left, fix: normal}}
      - {{boundary: right, fix: normal}}
      - {{boundary: front, fix: normal}}
      - {{boundary: back, fix: normal}}
      - {{boundary: bottom, fix: all}}
output: {{vtk: {{every: 0}}}}
)m",
                                       kMaterials);
  const auto run = testing::run_spec(read_model_from_string(text, "k0_3d.yaml"), "k0_3d");
  const Errors e = geostatic_errors(*run.model, k0_of);
  EXPECT_LT(e.displacement, 1e-9);
  EXPECT_LT(e.vertical, 1e-9);
  EXPECT_LT(e.ratio, 1e-9);
}

// Gravity loading, the alternative: gravity ramped on the weightless-stress soil. In 1D
// compression the Hencky law gives sigma_h / sigma_v = lambda / (lambda + 2 mu) = nu / (1 - nu)
// exactly, at any strain; sigma_v is the weight above to within the piecewise-constant stress
// of a cell (about a quarter of a cell's weight at a point, a few % of the base stress).
TEST(GravityLoading, LayeredGroundReachesOneDimensionalCompression) {
  const std::string phase = "    gravity: {acceleration: [0, -10], ramp: true}\n";
  auto spec = read_model_from_string(plane_strain_model(kTwoBodies, phase), "gravity.yaml");
  spec.phases.at(0).time_step.max = 0.25;
  const auto run = testing::run_spec(spec, "gravity_loading_layers");
  const auto poisson = [](const std::string& material) {
    const double nu = material == "sand" ? 0.3 : 0.4;
    return nu / (1 - nu);
  };
  const Errors e = geostatic_errors(*run.model, poisson);
  std::printf("[gravity loading] sigma_v error %.4f, nu/(1-nu) error %.2e\n", e.vertical, e.ratio);
  EXPECT_LT(e.ratio, 1e-6);
  EXPECT_LT(e.vertical, 0.06);
  const double weight = 2.0 * g * (sand_density * 6.0 + clay_density * 4.0);
  EXPECT_NEAR(run.column("base").back(), weight, 1e-8 * weight);
}

// ---------------------------------------------------------------------------------------------
// What the K0 procedure refuses, with the procedure's key path and line.

std::string build_error(const std::string& text) { return testing::build_error(text, "k0.yaml"); }

TEST(K0Procedure, RefusesLayersThatAreNotHorizontal) {
  const std::string bodies =
      R"m(  sand_layer: {material: sand, region: {polygon: [[0, 3], [2, 5], [2, 10], [0, 10]]}}
  clay_layer: {material: clay, region: {polygon: [[0, 0], [2, 0], [2, 5], [0, 3]]}}
)m";
  const std::string text = plane_strain_model(bodies, kK0Phase);
  const std::string message = build_error(text);
  // The error names the procedure's line.
  const auto line = 1 + std::count(text.begin(), text.begin() + text.find("k0_procedure"), '\n');
  EXPECT_EQ(message.rfind(fmt::format("k0.yaml:{}: phases[0].k0_procedure: the layers are not "
                                      "horizontal",
                                      line),
                          0),
            0u)
      << message;
}

TEST(K0Procedure, RefusesASlopingSurface) {
  const std::string bodies =
      "  slope: {material: sand, region: {polygon: [[0, 0], [2, 0], [2, 8], [0, 10]]}}\n";
  const std::string message = build_error(plane_strain_model(bodies, kK0Phase));
  EXPECT_NE(message.find("phases[0].k0_procedure: the ground is not level"), std::string::npos)
      << message;
}

TEST(K0Procedure, RefusesAStressOutsideTheTrescaSurface) {
  // |sigma_v - sigma_h| = 0.5 x 20 z exceeds 2 s_u = 10 below 1 m.
  std::string text = plane_strain_model(
      "  clay_layer: {material: soft, region: {box: {min: [0, 0], max: [2, 10]}}}\n",
      "    k0_procedure: {K0: 0.5}\n    gravity: {acceleration: [0, -10]}\n");
  text.replace(text.find("bodies:"), 0,
               "  soft: {model: tresca, su: 5, E: 1000, nu: 0.49, density: 2.0}\n");
  const std::string message = build_error(text);
  EXPECT_NE(message.find("phases[0].k0_procedure: the K0 stress of the point at"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("outside the yield surface of 'tresca'"), std::string::npos) << message;
  EXPECT_NE(message.find("> 2 s_u"), std::string::npos) << message;
}

TEST(K0Procedure, SetsOnlyItsBodiesAndDefaultsToJakyForMohrCoulomb) {
  // A weightless plate on the surface is not soil: it keeps a zero stress. Mohr-Coulomb sand
  // with phi = 30 takes K0 = 1 - sin 30 = 0.5.
  std::string text = plane_strain_model(
      "  soil: {material: mc_sand, region: {box: {min: [0, 0], max: [2, 10]}}}\n"
      "  plate: {material: sand, region: {box: {min: [0, 10], max: [1, 11]}}}\n",
      "    k0_procedure: {bodies: [soil]}\n    gravity: {acceleration: [0, -10]}\n");
  text.replace(text.find("bodies:"), 0,
               "  mc_sand: {model: mohr_coulomb, c: 0, phi: 30, psi: 0, E: 20000, nu: 0.3, "
               "density: 1.8}\n");
  const auto model = build_model(read_model_from_string(text, "k0.yaml"));
  const auto& p = model->points;
  for (Index i = 0; i < p.size(); ++i) {
    if (model->spec.bodies[p.body[i]].name == "plate") {
      EXPECT_EQ(p.stress[i].norm(), 0.0);
      continue;
    }
    const double y = p.position[i].y();
    EXPECT_NEAR(p.stress[i](1, 1), -18.0 * (10.0 - y), 1e-10);
    EXPECT_NEAR(p.stress[i](0, 0), 0.5 * p.stress[i](1, 1), 1e-10);
  }
}

TEST(K0Procedure, FindsTheSurfaceAndLayersAlongTheVertical) {
  const auto model =
      build_model(read_model_from_string(plane_strain_model(kLayeredBody, kK0Phase), "k0.yaml"));
  const SoilProfile profile = soil_profile(*model, {0}, Vec3(0.5, 0.0, 0.0));
  ASSERT_EQ(profile.segments.size(), 2u);
  EXPECT_NEAR(profile.surface, 10.0, 1e-12);
  EXPECT_NEAR(profile.segments[0].top, 4.0, 1e-12);
  EXPECT_NEAR(profile.segments[0].bottom, 0.0, 1e-12);
  EXPECT_NEAR(profile.mass_above(2.0, {1.8, 2.0}), 1.8 * 6 + 2.0 * 2, 1e-10);
}

}  // namespace
}  // namespace geompm
