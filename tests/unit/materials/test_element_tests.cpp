// Element tests with closed forms (docs/materials.md §4), run through the single-point driver:
// drained and undrained triaxial compression, triaxial extension and simple shear, for Tresca
// and Mohr-Coulomb. Stresses are Kirchhoff stresses, the ones the yield criteria are written in.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "geompm/materials/linear_elastic.hpp"
#include "geompm/materials/mohr_coulomb.hpp"
#include "geompm/materials/parameters.hpp"
#include "geompm/materials/principal_return.hpp"
#include "geompm/materials/single_point_driver.hpp"
#include "geompm/materials/tresca.hpp"
#include "material_test_support.hpp"

namespace geompm {
namespace {

constexpr int xx = 0, yy = 1, zz = 2, xy = 3;
constexpr Control strain = Control::strain, stress = Control::stress;
constexpr double deg = std::numbers::pi / 180;

// All six components stress-controlled to an isotropic stress -p (a consolidation).
PathSegment isotropic(double p) {
  PathSegment s;
  s.control.fill(stress);
  s.final_stress << -p, -p, -p, 0, 0, 0;
  s.increments = 5;
  return s;
}

// Axial (zz) strain with the radial stresses held at -p and no shear: a drained triaxial test.
PathSegment drained_triaxial(double axial_strain, double p, int increments) {
  PathSegment s;
  s.control = {stress, stress, strain, strain, strain, strain};
  s.strain_increment(zz) = axial_strain;
  s.final_stress << -p, -p, 0, 0, 0, 0;
  s.increments = increments;
  return s;
}

Tresca make_clay(double su, double E, double nu) {
  Tresca::Parameters p;
  p.youngs_modulus = E;
  p.poisson_ratio = nu;
  p.strength = su;
  return Tresca(p);
}

// The driver itself: uniaxial stress on a linear elastic (Hencky) material, tau_zz = E eps_zz and
// eps_xx = -nu eps_zz exactly, in one Newton iteration per increment (a linear problem).
TEST(SinglePointDriver, UniaxialStressOnLinearElasticity) {
  const LinearElastic steel(200.0, 0.25, 0.0);
  SinglePointDriver driver(steel);
  PathSegment s;
  s.control = {stress, stress, strain, stress, stress, stress};
  s.strain_increment(zz) = -0.1;
  s.increments = 4;
  for (const DriverState& state : driver.follow(s)) {
    EXPECT_LE(state.iterations, 1);
    EXPECT_NEAR(state.stress(2, 2), 200.0 * state.strain(2, 2), 1e-9);
    EXPECT_NEAR(state.strain(0, 0), -0.25 * state.strain(2, 2), 1e-12);
    EXPECT_NEAR(state.stress(0, 0), 0.0, 1e-9);
  }
}

// Undrained (constant-volume) triaxial compression on Tresca: eps_xx = eps_yy = -eps_zz / 2.
// Elastic: q = tau_xx - tau_zz = 2G (eps_xx - eps_zz) = 3G |d eps_zz|, so failure at
// |d eps_zz| = 2 s_u / 3G; then q = 2 s_u (eq. M.9) with the mean stress unchanged (no volume
// change, isochoric flow). The failure state lies on the left edge tau_1 = tau_2.
TEST(ElementTests, TrescaUndrainedTriaxialCompression) {
  const double su = 10, E = 5000, nu = 0.49, G = shear_modulus(E, nu), p0 = 100;
  const Tresca clay = make_clay(su, E, nu);
  SinglePointDriver driver(clay);
  driver.follow(isotropic(p0));
  const double start = driver.state().strain(2, 2);
  PathSegment s;
  s.strain_increment << 0.01, 0.01, -0.02, 0, 0, 0;
  s.increments = 200;
  for (const DriverState& state : driver.follow(s)) {
    const double axial = start - state.strain(2, 2);
    const double q = state.stress(0, 0) - state.stress(2, 2);
    EXPECT_NEAR(q, std::min(3 * G * axial, 2 * su), 1e-9 * su) << "axial strain " << axial;
    EXPECT_NEAR(state.stress.trace() / 3, -p0, 1e-9 * p0);
    EXPECT_EQ(state.iterations, 0);  // strain-controlled
  }
  EXPECT_NEAR(driver.state().stress(0, 0) - driver.state().stress(2, 2), 2 * su, 1e-10 * su);
  EXPECT_GT(driver.state().internal[Tresca::plastic_strain_index], 0.01);
}

// Drained triaxial compression on Tresca (radial stress held): q_f = 2 s_u at any confinement.
TEST(ElementTests, TrescaDrainedTriaxialCompression) {
  const double su = 25, E = 1e4, nu = 0.45;
  for (double p0 : {0.0, 50.0, 400.0}) {
    const Tresca clay = make_clay(su, E, nu);
    SinglePointDriver driver(clay);
    if (p0 > 0) driver.follow(isotropic(p0));
    int most_iterations = 0;
    for (const DriverState& state : driver.follow(drained_triaxial(-0.03, p0, 150))) {
      EXPECT_LE(state.stress(0, 0) - state.stress(2, 2), 2 * su * (1 + 1e-10));
      EXPECT_NEAR(state.stress(0, 0), -p0, 1e-8 * (p0 + su));
      most_iterations = std::max(most_iterations, state.iterations);
    }
    EXPECT_NEAR(driver.state().stress(0, 0) - driver.state().stress(2, 2), 2 * su, 1e-10 * su);
    EXPECT_LE(most_iterations, 4);  // the consistent tangent: Newton converges in a few steps
  }
}

// Simple shear on Tresca, with the other strains fixed or with the vertical stress held: the
// horizontal plane carries tau_xy = G gamma until tau_xy = s_u, where the principal stresses
// -p +- tau_xy reach tau_1 - tau_3 = 2 s_u with tau_2 = tau_zz = -p in the middle (main plane).
TEST(ElementTests, TrescaSimpleShear) {
  const double su = 10, E = 3000, nu = 0.49, G = shear_modulus(E, nu), p0 = 80;
  for (bool constant_vertical_stress : {false, true}) {
    const Tresca clay = make_clay(su, E, nu);
    SinglePointDriver driver(clay);
    driver.follow(isotropic(p0));
    PathSegment s;
    if (constant_vertical_stress) {
      s.control[yy] = stress;
      s.final_stress(yy) = -p0;
    }
    s.strain_increment(xy) = 0.02;  // gamma_xy = 0.04
    s.increments = 100;
    for (const DriverState& state : driver.follow(s)) {
      const double gamma = 2 * state.strain(0, 1);
      EXPECT_NEAR(state.stress(0, 1), std::min(G * gamma, su), 1e-9 * su) << "gamma " << gamma;
    }
    EXPECT_NEAR(driver.state().stress(0, 1), su, 1e-10 * su);
  }
}

// Drained triaxial compression on Mohr-Coulomb from an isotropic stress -p0: the radial stress
// is tau_1 = tau_2 = -p0 and the axial one tau_3; f = 0 (eq. M.12) on the left edge gives
//   q_f = tau_1 - tau_3 = 2 (c cos phi + p0 sin phi) / (1 - sin phi),
// the classical (tau_1 - tau_3)_f = 2 c cos phi - (tau_1 + tau_3) sin phi. At failure the stress
// is constant, so the strain increments are plastic: on the left edge the two flows share equally,
// d eps_p = dgamma (1 + sin psi, 1 + sin psi, -2 (1 - sin psi)), hence the dilatancy ratio
//   -d eps_v / d eps_axial = 2 sin psi / (1 - sin psi)      (Vermeer & de Borst 1984).
TEST(ElementTests, MohrCoulombDrainedTriaxialCompression) {
  const double c = 5, E = 1e4, nu = 0.3;
  for (const auto& [phi, psi] : {std::pair{30.0, 10.0}, {30.0, 0.0}, {35.0, 35.0}, {20.0, 5.0}})
    for (double p0 : {20.0, 100.0, 300.0}) {
      const double sf = std::sin(phi * deg), cf = std::cos(phi * deg), sd = std::sin(psi * deg);
      const double q_f = 2 * (c * cf + p0 * sf) / (1 - sf);
      // The driver holds the radial stress at -p0 only to its tolerance (1e-10 of the stresses
      // in play), and q_f moves with it by (1 + sin phi) / (1 - sin phi) times as much: the
      // yield condition is checked at the radial stress reached, tau_1 the larger of the two
      // (f = 0 on the left edge: q = 2 (c cos phi - tau_1 sin phi) / (1 - sin phi)).
      const auto strength = [&](const DriverState& s) {
        const double tau_1 = std::max(s.stress(0, 0), s.stress(1, 1));
        return 2 * (c * cf - tau_1 * sf) / (1 - sf);
      };
      const MohrCoulomb sand = test_support::make_mohr_coulomb(c, phi, psi, E, nu);
      SinglePointDriver driver(sand);
      driver.follow(isotropic(p0));
      const auto history = driver.follow(drained_triaxial(-0.2, p0, 400));
      for (const DriverState& state : history) {
        // Inside the surface, or outside by no more than the return's own tolerance: a trial
        // state with f <= kkt_tolerance x (the largest stress) is taken as elastic
        // (principal_return.hpp), and f = q (1 - sin phi) - (the strength's) on this edge.
        const double q = std::max(state.stress(0, 0), state.stress(1, 1)) - state.stress(2, 2);
        const double slack = kkt_tolerance * state.stress.cwiseAbs().maxCoeff() / (1 - sf);
        EXPECT_LE(q, strength(state) + slack) << "q / q_f - 1 = " << q / strength(state) - 1
                                              << ", phi " << phi << " psi " << psi << " p0 " << p0;
        EXPECT_LE(state.iterations, 4);
      }
      const DriverState& last = history.back();
      const DriverState& before = history[history.size() - 2];
      EXPECT_NEAR(last.stress(0, 0) - last.stress(2, 2), strength(last), 1e-10 * q_f)
          << "phi " << phi << " psi " << psi << " p0 " << p0;
      EXPECT_NEAR(strength(last), q_f, 1e-8 * q_f);  // the radial stress held at -p0
      // The dilatancy of the plastic strain increment (the elastic part of the total one is the
      // driver's tolerance, not zero).
      const Mat3 plastic =
          (last.strain - last.elastic_strain) - (before.strain - before.elastic_strain);
      EXPECT_NEAR(-plastic.trace() / plastic(2, 2), 2 * sd / (1 - sd), 1e-10)
          << "phi " << phi << " psi " << psi;
    }
}

// The same test on the rounded surface (docs/materials.md §3.6, eq. M.20): in triaxial
// compression theta = +30 deg, where K = A - B (the corner rounded from theta_T), and with
// p = -(p0 + q/3), J = q / sqrt(3), F = 0 reads
//   sqrt(q^2 K^2 / 3 + a^2 sin^2 phi) = c cos phi + (p0 + q/3) sin phi,
// a quadratic in q. A and B are computed here from K's continuity at theta_T, as in Abbo & Sloan.
TEST(ElementTests, RoundedMohrCoulombDrainedTriaxialCompression) {
  const double c = 5, E = 1e4, nu = 0.3, phi = 30, psi = 20, transition = 25;
  const double sf = std::sin(phi * deg), cf = std::cos(phi * deg), t = transition * deg;
  const double dk = -std::sin(t) - std::cos(t) * sf / std::sqrt(3.0);  // dK/dtheta at theta_T
  const double b = -dk / (3 * std::cos(3 * t));
  const double k30 = std::cos(t) - std::sin(t) * sf / std::sqrt(3.0) + b * std::sin(3 * t) - b;
  for (double a : {0.5, 5.0, 8.0})  // below the apex c cot(phi) = 8.66
    for (double p0 : {2.0, 20.0, 100.0}) {
      const double s0 = c * cf + p0 * sf;
      const double qa = k30 * k30 / 3 - sf * sf / 9, qb = -2 * sf / 3 * s0,
                   qc = a * a * sf * sf - s0 * s0;
      const double q_f = (-qb + std::sqrt(qb * qb - 4 * qa * qc)) / (2 * qa);
      const MohrCoulomb sand =
          test_support::make_rounded_mohr_coulomb(c, phi, psi, E, nu, a, transition);
      SinglePointDriver driver(sand);
      driver.follow(isotropic(p0));
      const auto history = driver.follow(drained_triaxial(-0.2, p0, 400));
      // Never above the limit beyond the model's tolerance: a trial state within
      // kkt_tolerance (1e-9 of the stress) of the surface is taken as elastic.
      for (const DriverState& state : history)
        EXPECT_LE(state.stress(0, 0) - state.stress(2, 2), q_f * (1 + kkt_tolerance))
            << (state.stress(0, 0) - state.stress(2, 2)) / q_f - 1;
      const DriverState& last = history.back();
      EXPECT_NEAR(last.stress(0, 0) - last.stress(2, 2), q_f, 1e-9 * q_f)
          << "a " << a << " p0 " << p0;
    }
}

// Drained triaxial extension (axial stress rising from -p0 with the radial stresses held):
// tau_1 is the axial stress, tau_2 = tau_3 = -p0, the right edge; f = 0 gives
//   q_e = tau_1 - tau_3 = 2 (c cos phi + p0 sin phi) / (1 + sin phi).
TEST(ElementTests, MohrCoulombDrainedTriaxialExtension) {
  const double c = 5, phi = 30, psi = 10, E = 1e4, nu = 0.3, p0 = 100;
  const double sf = std::sin(phi * deg);
  const double q_e = 2 * (c * std::cos(phi * deg) + p0 * sf) / (1 + sf);
  const MohrCoulomb sand = test_support::make_mohr_coulomb(c, phi, psi, E, nu);
  SinglePointDriver driver(sand);
  driver.follow(isotropic(p0));
  driver.follow(drained_triaxial(0.03, p0, 150));
  EXPECT_NEAR(driver.state().stress(2, 2) - driver.state().stress(0, 0), q_e, 1e-10 * q_e);
}

// Simple shear with every other strain fixed, from zero stress, psi = 0: the plastic flow keeps
// the volume, so the mean stress stays zero and the principal stresses are +-tau_xy, 0 (tau_2 = 0
// in the middle: main plane). f = 2 tau_xy - 2 c cos phi = 0:   tau_f = c cos phi.
TEST(ElementTests, MohrCoulombConstrainedSimpleShearAtZeroMeanStress) {
  const double c = 8, phi = 25, E = 1e4, nu = 0.3, G = shear_modulus(E, nu);
  const MohrCoulomb sand = test_support::make_mohr_coulomb(c, phi, 0.0, E, nu);
  SinglePointDriver driver(sand);
  PathSegment s;
  s.strain_increment(xy) = 0.01;
  s.increments = 100;
  for (const DriverState& state : driver.follow(s)) {
    const double gamma = 2 * state.strain(0, 1);
    EXPECT_NEAR(state.stress(0, 1), std::min(G * gamma, c * std::cos(phi * deg)), 1e-9 * c);
    EXPECT_NEAR(state.stress.trace(), 0.0, 1e-9 * c);
  }
  EXPECT_NEAR(driver.state().stress(0, 1), c * std::cos(phi * deg), 1e-10 * c);
}

// Simple shear under a constant vertical stress -sigma_n, eps_xx = eps_zz = 0 (a drained direct
// simple shear test). Once the stress no longer changes, the strain increments are plastic and
// the horizontal direction does not stretch: with the flow of eq. M.12 at angle theta to the
// principal axes, cos 2 theta = -sin psi; with tau_yy = -sigma_n and f = 0 this gives
//   tau_f = cos psi (c cos phi + sigma_n sin phi) / (1 - sin phi sin psi),
// which is c + sigma_n tan phi for psi = phi and c cos phi + sigma_n sin phi for psi = 0 (Davis
// 1968). The stress approaches it as the shear strain grows.
TEST(ElementTests, MohrCoulombSimpleShearUnderConstantVerticalStress) {
  const double c = 5, E = 1e4, nu = 0.3, sigma_n = 100;
  for (const auto& [phi, psi] : {std::pair{30.0, 0.0}, {30.0, 10.0}, {30.0, 30.0}}) {
    const double sf = std::sin(phi * deg), sd = std::sin(psi * deg);
    const double tau_f =
        std::cos(psi * deg) * (c * std::cos(phi * deg) + sigma_n * sf) / (1 - sf * sd);
    const MohrCoulomb sand = test_support::make_mohr_coulomb(c, phi, psi, E, nu);
    SinglePointDriver driver(sand);
    driver.follow(isotropic(sigma_n));
    PathSegment s;
    s.control[yy] = stress;
    s.final_stress(yy) = -sigma_n;
    s.strain_increment(xy) = 0.5;
    s.increments = 2000;
    double largest = 0;
    for (const DriverState& state : driver.follow(s))
      largest = std::max(largest, state.stress(0, 1));
    EXPECT_LE(largest, tau_f * (1 + 1e-8));
    EXPECT_NEAR(driver.state().stress(0, 1), tau_f, 1e-7 * tau_f)
        << "phi " << phi << " psi " << psi;
  }
}

}  // namespace
}  // namespace geompm
