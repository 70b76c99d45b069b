// Tresca (docs/materials.md §2): the return reaches the face of the prism a trial state belongs
// to, its tangent is the derivative of the update in every region, the stress stays on the
// surface and rotates with the trial strain, and s_u varies with depth as eq. M.11 says.
#include <gtest/gtest.h>

#include <bit>
#include <random>
#include <tuple>

#include "geompm/core/error.hpp"
#include "geompm/materials/parameters.hpp"
#include "geompm/materials/tresca.hpp"
#include "material_test_support.hpp"

namespace geompm {
namespace {

using namespace geompm::test_support;

constexpr double su = 10.0, modulus_ratio = 500.0, nu = 0.49;

Tresca make_clay(SurfaceTangent surface = SurfaceTangent::elastic) {
  Tresca::Parameters p;
  p.surface_tangent = surface;
  p.modulus_to_strength = modulus_ratio;
  p.poisson_ratio = nu;
  p.strength = su;
  return Tresca(p);
}

InternalVariables seeded(const Tresca& m) {
  InternalVariables internal{};
  m.initialise_point(Vec3(1.0, -2.0, 0.0), 2, internal);
  return internal;
}

Mat3 elasticity(double E) { return principal_elasticity(lame_lambda(E, nu), shear_modulus(E, nu)); }

// The planes of eq. M.9, written out here again rather than taken from the model.
std::vector<YieldPlane> prism(double s) {
  const Vec3 n0(1, 0, -1), n1(1, -1, 0), n2(0, 1, -1);
  return {{n0, n0, 2 * s}, {n1, n1, 2 * s}, {n2, n2, 2 * s}};
}

// A returned stress on the face `mask` (interior of the face) and positive multipliers for the
// flows of its planes.
struct Face {
  Vec3 stress;
  std::vector<double> gamma;
};

Face random_face(unsigned mask, std::mt19937& rng) {
  std::uniform_real_distribution<double> mean(-200, 50), inside(-0.9, 0.9), multiplier(0.2, 3.0);
  const double m = mean(rng), E = modulus_ratio * su;
  Face f;
  if (mask == Tresca::main_plane) f.stress = Vec3(m + su, m + inside(rng) * su, m - su);
  if (mask == Tresca::right_edge) f.stress = Vec3(m + su, m - su, m - su);
  if (mask == Tresca::left_edge) f.stress = Vec3(m + su, m + su, m - su);
  for (int k = 0; k < std::popcount(mask); ++k) f.gamma.push_back(multiplier(rng) * su / E);
  return f;
}

TEST(Tresca, ReturnsToTheFaceTheTrialStateWasBuiltFrom) {
  const Tresca clay = make_clay();
  const InternalVariables internal = seeded(clay);
  const double E = internal[Tresca::modulus_index];
  std::mt19937 rng(11);
  for (unsigned mask : {Tresca::main_plane, Tresca::right_edge, Tresca::left_edge})
    for (int sample = 0; sample < 50; ++sample) {
      const Face f = random_face(mask, rng);
      const Vec3 eps = trial_strain_for(f.stress, elasticity(E), prism(su), mask, f.gamma);
      const PrincipalReturn r = clay.principal_return(sorted_descending(eps), internal);
      ASSERT_EQ(r.active, mask);
      EXPECT_LT((r.stress - f.stress).norm(), 1e-10 * (f.stress.norm() + su));
      EXPECT_NEAR(r.stress(0) - r.stress(2), 2 * su, 1e-10 * su);
      EXPECT_NEAR(r.plastic_strain.sum(), 0.0, 1e-14);  // isochoric flow
    }
}

// A trial state exactly on a face keeps its stress; with `surface_tangent: plastic` the return
// reports the face and its tangent (M.6), that of the trial states beyond the face; by default the
// elastic one (docs/materials.md §1.7).
TEST(Tresca, OnTheSurfaceTheTangentIsThePlasticSidesWhenAskedFor) {
  const Tresca clay = make_clay(SurfaceTangent::plastic), by_default = make_clay();
  InternalVariables internal = seeded(clay);
  const InternalVariables never_yielded = internal;
  internal[Tresca::plastic_strain_index] = 1e-3;  // yielded in an earlier step (§1.7)
  const Mat3 de = elasticity(internal[Tresca::modulus_index]);
  std::mt19937 rng(12);
  for (unsigned mask : {Tresca::main_plane, Tresca::right_edge, Tresca::left_edge})
    for (int sample = 0; sample < 20; ++sample) {
      const Face f = random_face(mask, rng);
      const Vec3 on = sorted_descending(de.inverse() * f.stress);
      const PrincipalReturn at = clay.principal_return(on, internal);
      const PrincipalReturn beyond = clay.principal_return(
          sorted_descending(trial_strain_for(f.stress, de, prism(su), mask, f.gamma)), internal);
      EXPECT_EQ(at.active, mask);
      EXPECT_LT((at.stress - f.stress).norm(), 1e-10 * (f.stress.norm() + su));
      EXPECT_EQ(at.plastic_strain, Vec3::Zero());
      EXPECT_LT((at.tangent - beyond.tangent).norm(), 1e-10 * de.norm());
      const PrincipalReturn elastic = by_default.principal_return(on, internal);
      EXPECT_EQ(elastic.active, 0u);
      EXPECT_EQ(elastic.tangent, de);
      // A point that has never yielded reports the elastic side's tangent.
      const PrincipalReturn virgin = clay.principal_return(on, never_yielded);
      EXPECT_EQ(virgin.active, 0u);
      EXPECT_EQ(virgin.tangent, de);
    }
}

// dSPO §8.1 picks the edge before solving: when the return to the main plane breaks the order
// of the principal stresses, the right edge if tau_1 + tau_3 - 2 tau_2 > 0, else the left one.
TEST(Tresca, EdgeAgreesWithTheClosedFormCriterion) {
  const Tresca clay = make_clay();
  const InternalVariables internal = seeded(clay);
  const double E = internal[Tresca::modulus_index];
  std::mt19937 rng(12);
  std::uniform_real_distribution<double> u(-1, 1);
  int edges = 0;
  for (int sample = 0; sample < 2000; ++sample) {
    const Vec3 eps = sorted_descending(Vec3(u(rng), u(rng), u(rng)) * 10 * su / E);
    const Vec3 trial = elasticity(E) * eps;
    const PrincipalReturn r = clay.principal_return(eps, internal);
    if (trial(0) - trial(2) <= 2 * su) {
      EXPECT_EQ(r.active, 0u);
      continue;
    }
    // The main-plane return moves tau_1 and tau_3 by -+ mu dgamma, 2 mu dgamma = (f / 2).
    const double shift = 0.5 * (trial(0) - trial(2) - 2 * su);
    const bool plane_valid = trial(0) - shift >= trial(1) && trial(1) >= trial(2) + shift;
    if (plane_valid) {
      EXPECT_EQ(r.active, Tresca::main_plane);
    } else {
      ++edges;
      EXPECT_EQ(r.active,
                trial(0) + trial(2) - 2 * trial(1) > 0 ? Tresca::right_edge : Tresca::left_edge);
    }
  }
  EXPECT_GT(edges, 100);
}

TEST(Tresca, TangentMatchesFiniteDifferencesInEveryRegion) {
  const Tresca clay = make_clay();
  const InternalVariables internal = seeded(clay);
  const double E = internal[Tresca::modulus_index];
  const Tensor4 elastic = isotropic_elasticity4(lame_lambda(E, nu), shear_modulus(E, nu));
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1, 1);
  for (unsigned mask : {0u, Tresca::main_plane, Tresca::right_edge, Tresca::left_edge})
    for (int sample = 0; sample < 20; ++sample) {
      Vec3 principal;
      if (mask == 0) {  // elastic: a deviator well inside the prism
        principal =
            elasticity(E).inverse() *
            Vec3(-100 + 0.6 * su * u(rng), -100 + 0.6 * su * u(rng), -100 + 0.6 * su * u(rng));
      } else {
        const Face f = random_face(mask, rng);
        principal = trial_strain_for(f.stress, elasticity(E), prism(su), mask, f.gamma);
      }
      ASSERT_EQ(clay.principal_return(sorted_descending(principal), internal).active, mask);
      const Mat3 eps = with_axes(principal, random_rotation(rng));
      StressUpdate out;
      clay.update(eps, internal, out);
      const Tensor4 fd = finite_difference_tangent(clay, eps, internal, 1e-8);
      EXPECT_LT(tangent_error(fd, out.tangent, elastic), 1e-6) << "region " << mask;
    }
}

// Stresses of random trial states lie inside or on the prism, on it when the trial was outside,
// and rotate with the trial strain (any rotation or reflection, any order of the axes).
TEST(Tresca, StressOnTheSurfaceAndRotatesWithTheTrialStrain) {
  const Tresca clay = make_clay();
  const InternalVariables internal = seeded(clay);
  const double E = internal[Tresca::modulus_index];
  std::mt19937 rng(14);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int sample = 0; sample < 200; ++sample) {
    Mat3 a;
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) a(i, j) = u(rng);
    const Mat3 eps = (a + a.transpose()) * 4 * su / E;
    StressUpdate out;
    clay.update(eps, internal, out);
    const Vec3 tau = principal_descending(out.kirchhoff).values;
    const Vec3 trial = principal_descending(eps).values;
    const double trial_difference = 2 * shear_modulus(E, nu) * (trial(0) - trial(2));
    EXPECT_LE(tau(0) - tau(2), 2 * su * (1 + 1e-12));
    if (trial_difference > 2 * su) {
      EXPECT_NEAR(tau(0) - tau(2), 2 * su, 1e-10 * su);
      EXPECT_GT(out.internal[Tresca::plastic_strain_index], 0.0);
    }
    EXPECT_NEAR(out.kirchhoff.trace(),
                3 * lame_lambda(E, nu) * eps.trace() + 2 * shear_modulus(E, nu) * eps.trace(),
                1e-9 * std::abs(out.kirchhoff.trace()) + 1e-9);  // plastic flow is isochoric

    for (bool reflect : {false, true}) {
      const Mat3 rot = random_rotation(rng, reflect);
      StressUpdate turned;
      clay.update(rot * eps * rot.transpose(), internal, turned);
      EXPECT_LT((turned.kirchhoff - rot * out.kirchhoff * rot.transpose()).norm(),
                1e-10 * out.kirchhoff.norm());
      Tensor4 rr;  // (R (x) R)_(ij)(pq) = R_ip R_jq, so D' = (R(x)R) D (R(x)R)^T
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          for (int p = 0; p < 3; ++p)
            for (int q = 0; q < 3; ++q)
              rr(pair_index(i, j), pair_index(p, q)) = rot(i, p) * rot(j, q);
      EXPECT_LT((turned.tangent - rr * out.tangent * rr.transpose()).norm(),
                1e-8 * out.tangent.norm());
    }
  }
}

// Eq. M.11: s_u = su + su_gradient (su_reference_level - y), floored at su_min; E from E_over_su.
TEST(Tresca, StrengthAndStiffnessVaryWithDepth) {
  const auto clay = create_material("tresca", {{"E_over_su", 500},
                                               {"nu", 0.49},
                                               {"su", 2.3},
                                               {"su_gradient", 3.6},
                                               {"su_reference_level", 10.0},
                                               {"su_min", 1.0}});
  ASSERT_EQ(clay->internal_variable_count(), 3);
  EXPECT_STREQ(clay->internal_variable_name(Tresca::strength_index), "su");
  for (const auto& [position, dimension, expected_su] :
       std::vector<std::tuple<Vec3, int, double>>{{Vec3(3.0, 10.0, 0.0), 2, 2.3},
                                                  {Vec3(3.0, 8.5, 0.0), 2, 2.3 + 3.6 * 1.5},
                                                  {Vec3(3.0, 2.0, 0.0), 2, 2.3 + 3.6 * 8.0},
                                                  {Vec3(0.5, -7.0, 9.0), 3, 2.3 + 3.6 * 1.0},
                                                  {Vec3(0.0, 10.2, 0.0), 2, 2.3 - 0.72},
                                                  {Vec3(0.0, 11.0, 0.0), 2, 1.0}}) {
    InternalVariables internal{};
    clay->initialise_point(position, dimension, internal);
    EXPECT_NEAR(internal[Tresca::strength_index], expected_su, 1e-12) << position.transpose();
    EXPECT_NEAR(internal[Tresca::modulus_index], 500 * expected_su, 1e-9);
    // The point yields at its own s_u (undrained pure shear: tau_xy = s_u).
    Mat3 eps = Mat3::Zero();
    eps(0, 1) = eps(1, 0) = 0.05;
    StressUpdate out;
    clay->update(eps, internal, out);
    EXPECT_NEAR(out.kirchhoff(0, 1), expected_su, 1e-10 * expected_su);
  }
}

TEST(Tresca, FixedModulusAndNoGradient) {
  const auto clay = create_material("tresca", {{"E", 3000}, {"nu", 0.45}, {"su", 7}});
  InternalVariables internal{};
  clay->initialise_point(Vec3(0, -50, 0), 2, internal);
  EXPECT_EQ(internal[Tresca::strength_index], 7);
  EXPECT_EQ(internal[Tresca::modulus_index], 3000);
  EXPECT_EQ(clay->reference_modulus(), 3000);
  // A point that was never initialised is the reference-level soil.
  Mat3 eps = Mat3::Zero();
  eps(0, 1) = eps(1, 0) = 0.05;
  StressUpdate out;
  clay->update(eps, InternalVariables{}, out);
  EXPECT_NEAR(out.kirchhoff(0, 1), 7, 1e-12);
  EXPECT_EQ(out.internal[Tresca::strength_index], 7);
}

TEST(Tresca, NonPositiveStrengthAtAPointNamesSuMin) {
  const auto clay = create_material(
      "tresca",
      {{"E", 1000}, {"nu", 0.49}, {"su", 2}, {"su_gradient", 1}, {"su_reference_level", 0}});
  InternalVariables internal{};
  try {
    clay->initialise_point(Vec3(0, 3, 0), 2, internal);  // 1 m above where s_u reaches zero
    FAIL() << "expected ParameterError";
  } catch (const ParameterError& e) {
    EXPECT_EQ(e.key(), "su_min");
  }
}

}  // namespace
}  // namespace geompm
