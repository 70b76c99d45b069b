// Mohr-Coulomb rounded by the hyperbolic surface of Abbo & Sloan (1995) (`apex_rounding`,
// docs/materials.md §3.6). The surface: between the transition angles it is the cone's to within
// the rounding, its corners' rounding is smooth, its derivatives are those of its value, its tip
// lies at c / tan(phi) - a with a hydrostatic normal. The return: it reaches the surface with a
// flow along the potential's gradient for any trial state, keeps the principal order, its
// tangent is the derivative of the update everywhere, a hydrostatic trial state in tension
// returns to the tip with shear stiffness left (the sharp apex has none), far from the apex it
// is the cone's return, a return that cannot be solved says so, and bad parameters are refused.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <random>

#include "geompm/core/error.hpp"
#include "geompm/materials/hyperbolic_surface.hpp"
#include "geompm/materials/mohr_coulomb.hpp"
#include "geompm/materials/parameters.hpp"
#include "material_test_support.hpp"

namespace geompm {
namespace {

using namespace geompm::test_support;

constexpr double E = 1e4, nu = 0.3;

struct Case {
  double c, phi, psi, a;
};
// Associated and non-associated, a rounding small and large against the apex c / tan(phi).
const Case cases[] = {{10, 30, 30, 2}, {10, 30, 10, 2}, {1, 35, 20, 1.2}, {0.01, 30, 30, 0.015}};

MohrCoulomb make_rounded(const Case& cs) {
  return make_rounded_mohr_coulomb(cs.c, cs.phi, cs.psi, E, nu, cs.a);
}

double radians(double d) { return d * std::numbers::pi / 180; }
double apex_of(const Case& cs) { return cs.c / std::tan(radians(cs.phi)); }

const Mat3 de = principal_elasticity(lame_lambda(E, nu), shear_modulus(E, nu));
const Tensor4 elastic = isotropic_elasticity4(lame_lambda(E, nu), shear_modulus(E, nu));

// The principal stresses with mean p, deviator size j = sqrt(J2) and Lode angle theta
// (+30 deg: triaxial compression tau_1 = tau_2 > tau_3), sorted descending.
Vec3 stress_at(double p, double j, double theta) {
  // s = 2 J / sqrt(3) (sin(theta + 120 deg), sin(theta), sin(theta - 120 deg)), sorted for
  // |theta| <= 30 deg, for which J3 = -2 J^3 / (3 sqrt(3)) sin 3 theta.
  const double r = 2 * j / std::numbers::sqrt3, third = 2 * std::numbers::pi / 3;
  return Vec3::Constant(p) +
         r * Vec3(std::sin(theta + third), std::sin(theta), std::sin(theta - third));
}

// Random trial stresses around the tip and far along the cone, scaled to the apex.
Vec3 random_trial_stress(const Case& cs, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(-1, 1);
  const double apex = apex_of(cs);
  const double size = std::uniform_real_distribution<double>(0.3, 30)(rng) * apex;
  return Vec3::Constant(apex + size * u(rng)) + size * Vec3(u(rng), u(rng), u(rng));
}

// The Mohr-Coulomb function of the sharp cone, halved: (tau_1 - tau_3) / 2 + (tau_1 + tau_3) / 2
// sin(phi) - c cos(phi) (eq. M.12), which F approaches where K is the cone's.
double cone(const Case& cs, const Vec3& t) {
  return (t(0) - t(2)) / 2 + (t(0) + t(2)) / 2 * std::sin(radians(cs.phi)) -
         cs.c * std::cos(radians(cs.phi));
}

TEST(HyperbolicSurface, BetweenTheTransitionAnglesItIsTheConeToWithinTheRounding) {
  for (const Case& cs : cases) {
    const HyperbolicSurface f(cs.phi, cs.c, cs.a, 25);
    const double rounding = cs.a * std::sin(radians(cs.phi));
    for (double theta_deg : {-24.0, -10.0, 0.0, 12.0, 24.9})
      for (double j : {0.5, 5.0, 50.0}) {
        const Vec3 t = stress_at(-3 * apex_of(cs), j * apex_of(cs), radians(theta_deg));
        // sqrt(J^2 K^2 + A^2) - J K lies in (0, A^2 / (2 J K)].
        const double gap = f.value(t) - cone(cs, t);
        const double jk = cone(cs, t) - (t.sum() / 3 * std::sin(radians(cs.phi)) -
                                         cs.c * std::cos(radians(cs.phi)));
        EXPECT_GT(gap, 0);
        EXPECT_LE(gap, rounding * rounding / (2 * jk) * (1 + 1e-9));
      }
  }
}

TEST(HyperbolicSurface, CornersAreRoundedSmoothlyAndTheTipIsHydrostatic) {
  for (const Case& cs : cases) {
    const HyperbolicSurface f(cs.phi, cs.c, cs.a, 25);
    // K and dK/dx continuous at the transition x = sin 75 deg, on both sides.
    const double x = std::sin(radians(75));
    for (double sign : {1.0, -1.0}) {
      const auto below = f.lode_factor(sign * x * (1 - 1e-12));
      const auto above = f.lode_factor(sign * x * (1 + 1e-12));
      EXPECT_NEAR(below.k, above.k, 1e-9);
      EXPECT_NEAR(below.dk, above.dk, 1e-6 * std::abs(below.dk));
    }
    // At the corners (theta = +-30 deg, x = +-1) dK/dtheta = 3 cos(3 theta) dK/dx = 0, and K is
    // above the cone's there, so the deviatoric radius (c cos(phi) - p sin(phi)) / K is below
    // it: the rounding cuts the corner from inside, by a few %.
    for (double sign : {1.0, -1.0}) {
      const double theta = sign * radians(30);
      const double k_cone =
          std::cos(theta) - std::sin(theta) * std::sin(radians(cs.phi)) / std::numbers::sqrt3;
      const double k = f.lode_factor(sign).k;
      EXPECT_GE(k, k_cone);
      EXPECT_LT(k, k_cone * 1.05);
    }
    // The tip: F = 0 at c / tan(phi) - a on the axis, with a hydrostatic gradient.
    const auto tip = f.derivatives(Vec3::Constant(f.tip()));
    EXPECT_NEAR(f.tip(), apex_of(cs) - cs.a, 1e-12 * apex_of(cs));
    EXPECT_NEAR(tip.value, 0, 1e-12 * cs.c);
    EXPECT_LT((tip.gradient - Vec3::Constant(tip.gradient(0))).norm(), 1e-12);
  }
}

TEST(HyperbolicSurface, GradientAndHessianAreTheDerivativesOfTheValue) {
  std::mt19937 rng(30);
  for (const Case& cs : cases)
    for (double transition : {25.0, 29.0}) {
      const HyperbolicSurface f(cs.phi, cs.c, cs.a, transition);
      for (int sample = 0; sample < 200; ++sample) {
        const Vec3 t = sorted_descending(random_trial_stress(cs, rng));
        const auto d = f.derivatives(t);
        const double h = 1e-6 * std::max(cs.a, t.norm());
        Vec3 gradient;
        Mat3 hessian;
        for (int k = 0; k < 3; ++k) {
          const Vec3 e = h * Vec3::Unit(k);
          gradient(k) = (f.value(t + e) - f.value(t - e)) / (2 * h);
          hessian.col(k) =
              (f.derivatives(t + e).gradient - f.derivatives(t - e).gradient) / (2 * h);
        }
        SCOPED_TRACE(::testing::Message()
                     << "phi " << cs.phi << " a " << cs.a << " tau " << t.transpose());
        EXPECT_LT((gradient - d.gradient).norm(), 1e-6 * d.gradient.norm());
        EXPECT_LT((hessian - d.hessian).norm(), 1e-4 * d.hessian.norm() + 1e-9)
            << "hessian\n"
            << d.hessian << "\nfd\n"
            << hessian;
      }
    }
}

TEST(RoundedMohrCoulomb, ReturnsToTheSurfaceAlongThePotentialsGradient) {
  std::mt19937 rng(31);
  for (const Case& cs : cases) {
    const MohrCoulomb soil = make_rounded(cs);
    const HyperbolicSurface f(cs.phi, cs.c, cs.a, 25), g(cs.psi, 0, cs.a, 25);
    int plastic_states = 0;
    for (int sample = 0; sample < 3000; ++sample) {
      const Vec3 eps = sorted_descending(de.inverse() * random_trial_stress(cs, rng));
      const Vec3 trial = de * eps;
      const PrincipalReturn r = soil.principal_return(eps, {});
      const double tol = 1e-9 * std::max(trial.cwiseAbs().maxCoeff(), cs.c);
      SCOPED_TRACE(::testing::Message() << "phi " << cs.phi << " psi " << cs.psi << " a " << cs.a
                                        << " trial " << trial.transpose());
      EXPECT_TRUE(r.converged);
      EXPECT_LE(f.value(r.stress), tol);
      const std::optional<Vec3> plastic_or_none = checked_plastic_strain(r, trial, de, tol);
      if (!plastic_or_none) continue;
      const Vec3& plastic = *plastic_or_none;
      ++plastic_states;
      EXPECT_NEAR(f.value(r.stress), 0.0, tol);
      // The plastic strain is a non-negative multiple of dG at the returned stress.
      const Vec3 flow = g.derivatives(r.stress).gradient;
      const double dgamma = plastic.dot(flow) / flow.squaredNorm();
      EXPECT_GE(dgamma, 0);
      EXPECT_LT((plastic - dgamma * flow).norm(), 1e-8 * plastic.norm());
      EXPECT_LT((r.plastic_strain - plastic).norm(), 1e-8 * plastic.norm());
    }
    EXPECT_GT(plastic_states, 1000);
  }
}

TEST(RoundedMohrCoulomb, TangentMatchesFiniteDifferencesEverywhere) {
  std::mt19937 rng(32);
  for (const Case& cs : cases) {
    const MohrCoulomb soil = make_rounded(cs);
    int plastic_states = 0;
    for (int sample = 0; sample < 400; ++sample) {
      const Vec3 principal = de.inverse() * random_trial_stress(cs, rng);
      const Mat3 eps = with_axes(principal, random_rotation(rng));
      StressUpdate out;
      soil.update(eps, {}, out);
      plastic_states += soil.principal_return(sorted_descending(principal), {}).active != 0;
      // The step: small against the tip's radius (~ a), large enough that the return's Newton
      // tolerance (1e-12 of the stress) stays below the difference's resolution.
      const double h = 1e-5 * std::max(cs.a, cs.c) / E;
      const Tensor4 fd = finite_difference_tangent(soil, eps, {}, h);
      SCOPED_TRACE(::testing::Message() << "phi " << cs.phi << " psi " << cs.psi << " a " << cs.a
                                        << " principal " << principal.transpose());
      EXPECT_LT(tangent_error(fd, out.tangent, elastic), 1e-5);
    }
    EXPECT_GT(plastic_states, 100);
  }
}

// The tip: a trial state in hydrostatic tension returns to the tip, the hydrostatic stress
// c / tan(phi) - a, along the axis, and the tangent keeps stiffness in shear, where the sharp
// apex's tangent is zero (a vertex fixes the stress).
TEST(RoundedMohrCoulomb, HydrostaticTensionReturnsToTheTipWithShearStiffness) {
  for (const Case& cs : cases) {
    const MohrCoulomb soil = make_rounded(cs);
    const double tip = apex_of(cs) - cs.a;
    SCOPED_TRACE(::testing::Message() << "phi " << cs.phi << " psi " << cs.psi << " a " << cs.a);
    for (double beyond : {0.1, 1.0, 10.0}) {
      const double bulk3 = 3 * lame_lambda(E, nu) + 2 * shear_modulus(E, nu);
      const Mat3 eps = Mat3::Identity() * (tip + beyond * cs.c) / bulk3;
      StressUpdate out;
      soil.update(eps, {}, out);
      EXPECT_LT((out.kirchhoff - tip * Mat3::Identity()).norm(), 1e-9 * cs.c);
      Mat3 shear = Mat3::Zero();
      shear(0, 1) = shear(1, 0) = 1;
      const Mat3 response = unflatten(out.tangent * flatten(shear));
      EXPECT_GT(response(0, 1), 0.0);
      EXPECT_LT(response(0, 1), 2 * shear_modulus(E, nu) * (1 + 1e-12));
    }
  }
}

// Far from the apex, between the transition angles, the hyperbola meets its asymptote: the
// returns of the rounded and the sharp surface differ by O(a^2 sin(phi) / J).
TEST(RoundedMohrCoulomb, FarFromTheApexTheReturnIsTheCones) {
  const Case cs{10, 30, 20, 2};
  const MohrCoulomb rounded = make_rounded(cs);
  const MohrCoulomb sharp = make_mohr_coulomb(cs.c, cs.phi, cs.psi, E, nu);
  for (double p : {-100.0, -1000.0, -10000.0}) {
    const Vec3 trial = stress_at(p, std::abs(p), radians(5));
    const Vec3 eps = de.inverse() * trial;
    const PrincipalReturn a = rounded.principal_return(eps, {}),
                          b = sharp.principal_return(eps, {});
    ASSERT_EQ(b.active, MohrCoulomb::main_plane);
    const double sf = std::sin(radians(cs.phi));
    EXPECT_LT((a.stress - b.stress).norm(), 10 * cs.a * cs.a * sf / std::abs(p));
  }
}

// Where neither Newton's method nor the continuation reaches a solution (here a non-finite trial
// state) the return says so instead of handing back the nearest iterate, and the update passes it
// on (the engine then cuts the step back); the hydrostatic tension of the test above converges.
TEST(RoundedMohrCoulomb, AReturnThatCannotBeSolvedIsReportedNotUsed) {
  const Case cs = cases[3];
  const MohrCoulomb soil = make_rounded(cs);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_FALSE(soil.principal_return(Vec3(nan, 0, -1e-3), {}).converged);
  StressUpdate out;
  Mat3 eps = Mat3::Zero();
  eps(0, 0) = nan;
  soil.update(eps, {}, out);
  EXPECT_FALSE(out.converged);
  soil.update(Mat3::Identity() * 10 * cs.c / E, {}, out);
  EXPECT_TRUE(out.converged);
}

TEST(RoundedMohrCoulomb, BadRoundingIsRefusedNamingTheKey) {
  auto create = [](ParameterMap extra) {
    ParameterMap m{{"c", 10}, {"phi", 30}, {"psi", 30}, {"E", E}, {"nu", nu}};
    for (auto [k, v] : extra) m[k] = v;
    return MohrCoulomb::create(m);
  };
  EXPECT_NO_THROW(create({{"apex_rounding", 17}}));
  EXPECT_NO_THROW(create({{"apex_rounding", 1}, {"lode_transition", 29}}));
  const std::pair<ParameterMap, std::string> bad[] = {
      {{{"apex_rounding", 17.4}}, "apex_rounding"},                       // beyond c / tan(phi)
      {{{"apex_rounding", 2}, {"psi", 0}}, "apex_rounding"},              // psi = 0
      {{{"apex_rounding", 2}, {"phi", 0}, {"psi", 0}}, "apex_rounding"},  // no apex
      {{{"apex_rounding", -1}}, "apex_rounding"},
      {{{"apex_rounding", 2}, {"lode_transition", 30}}, "lode_transition"},
      {{{"lode_transition", 25}}, "lode_transition"},  // without the rounding
      {{{"apex_rounding", 2}, {"tension_cutoff", 1}}, "tension_cutoff"}};
  for (const auto& [extra, key] : bad) {
    try {
      create(extra);
      ADD_FAILURE() << "accepted a bad rounding; expected an error on " << key;
    } catch (const ParameterError& e) {
      EXPECT_EQ(e.key(), key) << e.what();
    }
  }
}

}  // namespace
}  // namespace geompm
