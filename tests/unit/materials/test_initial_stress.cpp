// Starting a point from a given stress (the K0 procedure, docs/theory.md §10): the elastic strain
// a material returns for a Kirchhoff stress gives that stress back through update(), for every
// model, for stresses with any principal axes; Tresca uses the point's own E; Mohr-Coulomb's
// default K0 is Jaky's 1 - sin(phi).
#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "geompm/materials/material.hpp"
#include "geompm/materials/mohr_coulomb.hpp"
#include "geompm/materials/tresca.hpp"
#include "material_test_support.hpp"

namespace geompm {
namespace {

using namespace geompm::test_support;

// A geostatic-like compressive stress with random principal axes, inside every yield surface
// below (principal values between -100 and -40 kPa).
Mat3 random_compression(std::mt19937& rng) {
  std::uniform_real_distribution<double> value(-100.0, -40.0);
  return with_axes(Vec3(value(rng), value(rng), value(rng)), random_rotation(rng));
}

void expect_stress_recovered(const Material& m, const InternalVariables& internal, int seed) {
  std::mt19937 rng(seed);
  for (int k = 0; k < 50; ++k) {
    const Mat3 tau = random_compression(rng);
    const auto eps = m.elastic_strain_for_stress(tau, internal);
    ASSERT_TRUE(eps.has_value()) << m.model_name();
    StressUpdate out;
    m.update(*eps, internal, out);
    EXPECT_LT((out.kirchhoff - tau).norm(), 1e-10 * tau.norm()) << m.model_name();
    EXPECT_LT((*eps - eps->transpose()).norm(), 1e-14) << m.model_name();
  }
}

TEST(InitialStress, EveryModelGivesTheStressBack) {
  for (const char* model : {"linear_elastic", "neo_hookean"}) {
    // A soft neo-Hookean solid: strains of several %, where it differs from Hencky.
    const auto m = create_material(model, {{"E", 2000.0}, {"nu", 0.3}});
    expect_stress_recovered(*m, {}, 1);
  }
  const auto mc = create_material(
      "mohr_coulomb", {{"c", 5.0}, {"phi", 30.0}, {"psi", 0.0}, {"E", 1.0e4}, {"nu", 0.3}});
  expect_stress_recovered(*mc, {}, 2);
}

TEST(InitialStress, TrescaUsesThePointsOwnModulus) {
  // E = 500 s_u with s_u growing with depth: two points at different depths have different E.
  const auto clay = create_material("tresca", {{"su", 40.0},
                                               {"su_gradient", 10.0},
                                               {"su_reference_level", 0.0},
                                               {"E_over_su", 500.0},
                                               {"nu", 0.49}});
  for (double y : {-1.0, -6.0}) {
    InternalVariables internal{};
    clay->initialise_point(Vec3(0.0, y, 0.0), 2, internal);
    expect_stress_recovered(*clay, internal, 3);
    // Isotropic compression p gives the volumetric strain p / K with the point's own K.
    const double E = internal[Tresca::modulus_index], K = E / (3 * (1 - 2 * 0.49));
    const auto eps = clay->elastic_strain_for_stress(-60.0 * Mat3::Identity(), internal);
    EXPECT_NEAR(eps->trace(), -60.0 / K, 1e-12 * 60.0 / K);
  }
}

TEST(InitialStress, AStressOutsideTheYieldSurfaceIsNotGivenBack) {
  // |sigma_v - sigma_h| = 60 > 2 s_u = 40: the update returns to the surface, which is how the
  // K0 procedure detects it.
  const auto clay = create_material("tresca", {{"su", 20.0}, {"E", 1.0e4}, {"nu", 0.49}});
  InternalVariables internal{};
  clay->initialise_point(Vec3::Zero(), 2, internal);
  const Mat3 tau = Vec3(-40.0, -100.0, -40.0).asDiagonal();
  StressUpdate out;
  clay->update(*clay->elastic_strain_for_stress(tau, internal), internal, out);
  EXPECT_GT((out.kirchhoff - tau).norm(), 1.0);
}

TEST(InitialStress, MohrCoulombDefaultK0IsJaky) {
  const auto sand = make_mohr_coulomb(0.0, 30.0, 0.0, 1.0e4, 0.3);
  ASSERT_TRUE(sand.default_k0().has_value());
  EXPECT_NEAR(*sand.default_k0(), 0.5, 1e-14);
  EXPECT_FALSE(create_material("linear_elastic", {{"E", 1.0}, {"nu", 0.3}})->default_k0());
}

}  // namespace
}  // namespace geompm
