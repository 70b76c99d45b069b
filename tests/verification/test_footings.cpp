// Footings without contact (docs/user-guide.md, "Footings"): a smooth or rough footing by the
// prescribed displacement of the grid nodes under it (grid_motion), and a stiff plate of
// material points under a prescribed force (load control). Closed forms on an elastic block,
// whose homogeneous deformation the grid represents exactly.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "run_model.hpp"

namespace geompm {
namespace {

constexpr double E = 10000.0, nu = 0.3, width = 1.0, height = 1.0;

// An elastic block [0, 1] x [0, 1] with rollers on its left (symmetry) and base, compressed by
// `motion` on the grid nodes of its top (the node set `base_of_footing`).
std::string block_under_grid_motion(const std::string& motion) {
  return fmt::format(R"m(analysis: {{kinematics: plane_strain}}
mesh: {{generate: {{x: {{length: 1.5, cells: 6}}, y: {{length: 1.25, cells: 5}}}}}}
materials:
  soil: {{model: linear_elastic, E: 10000, nu: 0.3}}
bodies:
  block: {{material: soil, region: {{box: {{min: [0, 0], max: [1, 1]}}}}}}
node_sets:
  base_of_footing: {{box: {{min: [0, 1], max: [1, 1]}}}}
phases:
  - name: push
    time_step: 0.25
    grid_motion:
      - {{boundary: base_of_footing, {}}}
    fixities:
      - {{boundary: left, fix: normal}}
      - {{boundary: bottom, fix: y}}
output:
  vtk: {{every: 0}}
  history:
    - {{quantity: displacement, boundary: base_of_footing, component: y, name: settlement}}
    - {{quantity: reaction, boundary: base_of_footing, component: y, name: force}}
    - {{quantity: reaction, boundary: bottom, component: y, name: base}}
# The empty cells beside the block resist its spread by about their stiffness over the block's
# (the default 1e-4 of it); 1e-6 keeps that below the tolerance of the exact first step.
numerics: {{empty_cell_stiffness: 1.0e-6}}
)m",
                     motion);
}

// Plane strain with the sides free (a smooth footing as wide as the block): tau_xx = 0,
// eps_zz = 0, so tau_yy = E / (1 - nu^2) ln(l) with l = 1 - d / H, and the force on the
// current width W l_x is sigma_yy W l_x = tau_yy W / l (J = l_x l).
double smooth_force(double settlement) {
  const double l = 1.0 - settlement / height;
  return E / (1 - nu * nu) * std::log(l) * width / l;
}

// Confined (oedometric) compression: tau_yy = E_oed ln(l), force sigma_yy W = tau_yy W / l.
double oedometric_modulus() { return E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)); }
double confined_force(double settlement) {
  const double l = 1.0 - settlement / height;
  return oedometric_modulus() * std::log(l) * width / l;
}

TEST(GridMotionFooting, SmoothFootingOfTheBlocksWidthGivesUniaxialPlaneStrain) {
  const auto run = testing::run_spec(
      read_model_from_string(block_under_grid_motion("displacement: [~, \"-0.01*t\"]"),
                             "smooth.yaml"),
      "footing_smooth");
  const auto settlement = run.column("settlement"), force = run.column("force"),
             base = run.column("base");
  ASSERT_EQ(settlement.size(), 5u);  // the initial state and 4 steps
  for (std::size_t k = 1; k < settlement.size(); ++k) {
    EXPECT_NEAR(settlement[k], -0.0025 * k, 1e-15);  // exactly what was prescribed
    const double exact = smooth_force(-settlement[k]);
    std::printf("[smooth footing, settlement %.4f] force %.4f, closed form %.4f\n", -settlement[k],
                force[k], exact);
    // The first step is exact: the top cell is full. Later the soil's top has moved below the
    // grid line the driven nodes stay on, the top cell is partly empty and the grid compresses
    // its empty part too: an error of about a quarter of the settlement / cell height (1 % at
    // a settlement of 4 % of the cell), the limit of a footing on grid nodes.
    EXPECT_NEAR(force[k], exact, (k == 1 ? 1e-5 : 0.02) * std::abs(exact)) << "step " << k;
    EXPECT_NEAR(base[k], -force[k], 1e-8 * std::abs(exact)) << "step " << k;  // weightless
  }
  // Smooth: the top of the block spreads freely.
  double spread = 0.0;
  for (Index p = 0; p < run.model->points.size(); ++p)
    spread = std::max(spread, run.model->points.displacement[p].x());
  EXPECT_GT(spread, 0.5 * 0.01 * nu / (1 - nu) * width);
}

TEST(GridMotionFooting, RoughFootingHoldsTheTopAndCarriesMore) {
  const auto smooth = testing::run_spec(
      read_model_from_string(block_under_grid_motion("displacement: [~, \"-0.01*t\"]"),
                             "smooth.yaml"),
      "footing_smooth_reference");
  const auto rough = testing::run_spec(
      read_model_from_string(block_under_grid_motion("displacement: [0, \"-0.01*t\"]"),
                             "rough.yaml"),
      "footing_rough");
  const double f_smooth = smooth.column("force").back(), f_rough = rough.column("force").back();
  std::printf(
      "[footing on a block, 1 %% settlement] force smooth %.3f, rough %.3f, confined %.3f\n",
      f_smooth, f_rough, confined_force(0.01));
  // Friction on the top restrains the spreading: stiffer than smooth, softer than confined.
  EXPECT_GT(std::abs(f_rough), 1.001 * std::abs(f_smooth));
  EXPECT_LT(std::abs(f_rough), std::abs(confined_force(0.01)));
  // The nodes of the footing's base do not move sideways.
  for (Index p = 0; p < rough.model->points.size(); ++p) {
    if (rough.model->points.initial_position[p].y() > 0.95) {
      EXPECT_LT(std::abs(rough.model->points.displacement[p].x()), 1e-3 * 0.01);
    }
  }
}

TEST(GridMotionFooting, VelocityAndAFixedNodeOnTheSymmetryAxis) {
  // A velocity gives the same motion; the corner node on the axis is fixed in x and driven in y.
  const auto run = testing::run_spec(
      read_model_from_string(block_under_grid_motion("velocity: [~, -0.01]"), "velocity.yaml"),
      "footing_velocity");
  const auto displaced = testing::run_spec(
      read_model_from_string(block_under_grid_motion("displacement: [~, \"-0.01*t\"]"), "d.yaml"),
      "footing_displacement");
  EXPECT_NEAR(run.column("settlement").back(), -0.01, 1e-15);
  EXPECT_NEAR(run.column("force").back(), displaced.column("force").back(),
              1e-10 * std::abs(displaced.column("force").back()));
}

TEST(GridMotionFooting, RefusesANodeSetWithoutNodesAndANodeDrivenTwice) {
  std::string text = block_under_grid_motion("displacement: [~, \"-0.01*t\"]");
  const std::string empty = std::string(text).replace(text.find("{min: [0, 1], max: [1, 1]}"), 26,
                                                      "{min: [0.1, 1], max: [0.2, 1]}");
  EXPECT_NE(testing::build_error(empty).find(
                "node_sets.base_of_footing: node set 'base_of_footing' holds "
                "no mesh node"),
            std::string::npos)
      << testing::build_error(empty);
  // The plane y = 1 holds the node set's nodes: both drive y there.
  const std::string twice = std::string(text).replace(
      text.find("    fixities:"), 0,
      "      - {plane: {axis: y, value: 1}, displacement: [~, \"-0.02*t\"]}\n");
  const std::string message = testing::build_error(twice);
  EXPECT_NE(message.find("phases[0].grid_motion[1]: the node at [0, 1, 0] is already driven in y "
                         "by phases[0].grid_motion[0]"),
            std::string::npos)
      << message;
}

// Load control: a stiff plate of material points on an elastic block in confined compression,
// pushed by a force q W growing with t. The plate's mean displacement (the settlement history)
// follows the Hencky closed form E_oed ln(l) / l = -q, l = 1 - s / H, at every step.
TEST(LoadControlledFooting, StiffPlateSettlesAsTheOedometricClosedForm) {
  const std::string text = R"m(analysis: {kinematics: plane_strain}
mesh: {generate: {x: {length: 1, cells: 4}, y: {length: 1.5, cells: 6}}}
materials:
  soil: {model: linear_elastic, E: 10000, nu: 0.3}
  steel: {model: linear_elastic, E: 1.0e7, nu: 0.3}
bodies:
  soil: {material: soil, region: {box: {min: [0, 0], max: [1, 1]}}}
  plate: {material: steel, region: {box: {min: [0, 1], max: [1, 1.25]}}}
point_sets:
  plate: {body: plate, region: all}
phases:
  - name: load
    time_step: 0.25
    newton: {residual_tolerance: 1.0e-7}
    loads:
      - {point_set: plate, force: [0, "-100*t"]}
    fixities:
      - {boundary: left, fix: normal}
      - {boundary: right, fix: normal}
      - {boundary: bottom, fix: all}
output:
  vtk: {every: 0}
  history:
    - {quantity: displacement, point_set: plate, component: y, name: settlement}
    - {quantity: load, point_set: plate, component: y, name: load}
    - {quantity: reaction, boundary: bottom, component: y, name: base}
)m";
  const auto run = testing::run_spec(read_model_from_string(text, "plate.yaml"), "footing_load");
  const auto settlement = run.column("settlement"), load = run.column("load"),
             base = run.column("base"), time = run.column("time");
  ASSERT_EQ(settlement.size(), 5u);
  for (std::size_t k = 1; k < settlement.size(); ++k) {
    const double q = 100.0 * time[k] / width;
    // Newton on E_oed ln(l) / l + q = 0 for the stretch of the soil.
    double l = 1.0;
    for (int i = 0; i < 50; ++i) {
      const double f = oedometric_modulus() * std::log(l) / l + q;
      const double df = oedometric_modulus() * (1 - std::log(l)) / (l * l);
      l -= f / df;
    }
    const double exact = -(1.0 - l) * height;
    std::printf("[plate under %.0f kPa] settlement %.6f, closed form %.6f\n", q, settlement[k],
                exact);
    // Exact in the first step; then the plate's points enter the top cell of the soil, whose
    // quadrature sees both: 0.8 % at a settlement of 3 % of the cell.
    EXPECT_NEAR(settlement[k], exact, (k == 1 ? 1e-4 : 0.02) * std::abs(exact)) << "step " << k;
    EXPECT_NEAR(load[k], -q * width, 1e-12);
    EXPECT_NEAR(base[k], q * width, 1e-6 * q * width);
  }
}

}  // namespace
}  // namespace geompm
