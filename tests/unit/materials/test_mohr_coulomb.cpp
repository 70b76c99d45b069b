// Mohr-Coulomb with tension cut-off (docs/materials.md §3): the return reaches the face a trial
// state belongs to (main plane, both edges, apex, the cut-off's plane, edges and corners), the
// Kuhn-Tucker conditions hold for any trial state, the tangent is the derivative of the update in
// every region, and the stress rotates with the trial strain.
#include <gtest/gtest.h>

#include <Eigen/QR>
#include <bit>
#include <cmath>
#include <numbers>
#include <optional>
#include <random>

#include "geompm/materials/mohr_coulomb.hpp"
#include "geompm/materials/parameters.hpp"
#include "material_test_support.hpp"

namespace geompm {
namespace {

using namespace geompm::test_support;

constexpr double c = 10.0, E = 1e4, nu = 0.3;

MohrCoulomb make_soil(double phi, double psi, double cutoff = -1,
                      SurfaceTangent surface = SurfaceTangent::elastic) {
  return make_mohr_coulomb(c, phi, psi, E, nu, cutoff, surface);
}

const Mat3 de = principal_elasticity(lame_lambda(E, nu), shear_modulus(E, nu));
// The state of a point that has yielded in an earlier step (docs/materials.md §1.7).
const InternalVariables yielded = [] {
  InternalVariables v{};
  v[MohrCoulomb::plastic_strain_index] = 1e-3;
  return v;
}();
const Tensor4 elastic = isotropic_elasticity4(lame_lambda(E, nu), shear_modulus(E, nu));

// Geometry of the surface of `soil` in the sextant tau_1 >= tau_2 >= tau_3.
struct Surface {
  double sf, k, apex, cutoff, tau3_at_cutoff;
  explicit Surface(const MohrCoulomb& soil, double phi, double cutoff_) {
    sf = std::sin(phi * std::numbers::pi / 180);
    k = 2 * c * std::cos(phi * std::numbers::pi / 180);
    apex = soil.apex();
    cutoff = cutoff_;
    // On the main plane with tau_1 = t (eq. M.12): tau_3 = (t (1 + sf) - k) / (1 - sf).
    tau3_at_cutoff = (cutoff * (1 + sf) - k) / (1 - sf);
  }
  double tau1_on_main_plane(double tau3) const { return (k + tau3 * (1 - sf)) / (1 + sf); }
};

// Which returned stress a face gives, and which planes' flows reach it. Faces named by the
// model's masks; `vertex_left` is the corner tau_1 = tau_2 = t on the main plane, where four
// planes meet (0, 2, 3, 4) and any three of them may be reported.
enum class Face {
  main,
  right,
  left,
  apex,
  tension,
  main_tension,
  tension_edge,
  tension_corner,
  vertex_right,
  vertex_left
};

struct FacePoint {
  Vec3 stress;
  unsigned flows;     // planes whose flows make up the trial state
  unsigned expected;  // the mask principal_return must report (0: any, check the stress)
};

FacePoint random_face_point(Face face, const Surface& s, std::mt19937& rng) {
  std::uniform_real_distribution<double> u(0.05, 0.95);
  double top = std::min(s.apex, s.tau3_at_cutoff);  // largest tau_3 on the main plane
  if (!std::isfinite(top)) top = 0;                 // phi = 0 and no cut-off: an open prism
  const double tau3 = top - 5 - 300 * u(rng);
  const double tau1 = s.tau1_on_main_plane(tau3);
  const double t = s.cutoff, t3 = s.tau3_at_cutoff;
  switch (face) {
    case Face::main:
      return {Vec3(tau1, tau3 + u(rng) * (tau1 - tau3), tau3), 0b1, MohrCoulomb::main_plane};
    case Face::right:
      return {Vec3(tau1, tau3, tau3), 0b11, MohrCoulomb::right_edge};
    case Face::left:
      return {Vec3(tau1, tau1, tau3), 0b101, MohrCoulomb::left_edge};
    case Face::apex:
      return {Vec3::Constant(s.apex), 0b111111, 0};
    case Face::tension: {
      const double lower = t3 + u(rng) * (t - t3);
      return {Vec3(t, lower + u(rng) * (t - lower), lower), 0b1000, MohrCoulomb::tension_plane};
    }
    case Face::main_tension:
      return {Vec3(t, t3 + u(rng) * (t - t3), t3), 0b1001, MohrCoulomb::main_tension_edge};
    case Face::tension_edge:
      return {Vec3(t, t, t3 + u(rng) * (t - t3)), 0b11000, MohrCoulomb::tension_edge};
    case Face::tension_corner:
      return {Vec3::Constant(t), 0b111000, MohrCoulomb::tension_corner};
    case Face::vertex_right:
      return {Vec3(t, t3, t3), 0b1011, 0b1011};
    case Face::vertex_left:
      return {Vec3(t, t, t3), 0b11101, 0};
  }
  return {};
}

Vec3 trial_for(const MohrCoulomb& soil, const FacePoint& f, std::mt19937& rng) {
  std::uniform_real_distribution<double> multiplier(0.2, 3.0);
  std::vector<double> gamma;
  for (int k = 0; k < std::popcount(f.flows); ++k) gamma.push_back(multiplier(rng) * c / E);
  return trial_strain_for(f.stress, de, soil.planes(), f.flows, gamma);
}

struct Case {
  double phi, psi, cutoff;  // cutoff < 0: the default (the apex)
  std::vector<Face> faces;
};

const std::vector<Case> cases = {
    {30, 10, -1, {Face::main, Face::right, Face::left, Face::apex}},
    {30, 0, -1, {Face::main, Face::right, Face::left, Face::apex}},
    {30, 30, -1, {Face::main, Face::right, Face::left, Face::apex}},
    {40, 15, -1, {Face::main, Face::right, Face::left, Face::apex}},
    {0, 0, -1, {Face::main, Face::right, Face::left}},
    {30,
     10,
     5.0,
     {Face::main, Face::right, Face::left, Face::tension, Face::main_tension, Face::tension_edge,
      Face::tension_corner, Face::vertex_right, Face::vertex_left}},
    {0,
     0,
     4.0,
     {Face::main, Face::right, Face::left, Face::tension, Face::main_tension, Face::tension_edge,
      Face::tension_corner, Face::vertex_right, Face::vertex_left}},
};

double stress_scale(const Vec3& s) { return s.cwiseAbs().maxCoeff() + c; }

TEST(MohrCoulomb, ReturnsToTheFaceTheTrialStateWasBuiltFrom) {
  std::mt19937 rng(21);
  for (const Case& cs : cases) {
    const MohrCoulomb soil = make_soil(cs.phi, cs.psi, cs.cutoff);
    const Surface s(soil, cs.phi, cs.cutoff >= 0 ? cs.cutoff : soil.apex());
    for (Face face : cs.faces)
      for (int sample = 0; sample < 40; ++sample) {
        const FacePoint f = random_face_point(face, s, rng);
        const PrincipalReturn r =
            soil.principal_return(sorted_descending(trial_for(soil, f, rng)), {});
        SCOPED_TRACE(::testing::Message() << "phi " << cs.phi << " psi " << cs.psi << " cutoff "
                                          << cs.cutoff << " face " << static_cast<int>(face));
        if (f.expected != 0) {
          EXPECT_EQ(r.active, f.expected);
        }
        EXPECT_LT((r.stress - f.stress).norm(), 1e-10 * stress_scale(f.stress));
        if (r.active != f.expected) {
          // At a vertex the stress is fixed: the tangent in principal space vanishes.
          EXPECT_EQ(std::popcount(r.active), 3);
          EXPECT_LT(r.tangent.norm(), 1e-10 * de.norm());
        }
      }
  }
}

// dSPO §8.2: when the main-plane return breaks the order of the principal stresses, the right
// edge if (1 - sin psi) tau_1 - 2 tau_2 + (1 + sin psi) tau_3 > 0, else the left edge.
TEST(MohrCoulomb, EdgeAgreesWithTheClosedFormCriterion) {
  const double phi = 30, psi = 10, sd = std::sin(psi * std::numbers::pi / 180);
  const MohrCoulomb soil = make_soil(phi, psi);
  std::mt19937 rng(22);
  std::uniform_real_distribution<double> u(-1, 1);
  int edges = 0;
  for (int sample = 0; sample < 3000; ++sample) {
    // Compressive trial states, well away from the apex.
    const Vec3 stress = Vec3::Constant(-150) + 120 * Vec3(u(rng), u(rng), u(rng));
    const Vec3 eps = sorted_descending(de.inverse() * stress);
    const Vec3 trial = de * eps;
    const PrincipalReturn r = soil.principal_return(eps, {});
    const PrincipalReturn plane = return_to_yield_planes(eps, de, std::span(soil.planes()).first(1),
                                                         std::vector<unsigned>{0b1});
    if (r.active == 0 ||
        (plane.stress(0) >= plane.stress(1) && plane.stress(1) >= plane.stress(2))) {
      EXPECT_TRUE(r.active == 0 || r.active == MohrCoulomb::main_plane);
      continue;
    }
    ++edges;
    const double criterion = (1 - sd) * trial(0) - 2 * trial(1) + (1 + sd) * trial(2);
    EXPECT_EQ(r.active, criterion > 0 ? MohrCoulomb::right_edge : MohrCoulomb::left_edge);
  }
  EXPECT_GT(edges, 100);
}

// For any trial state: every plane holds, the order tau_1 >= tau_2 >= tau_3 holds, and the plastic
// strain (D^e)^-1 (tau_tr - tau) is a non-negative combination of the flows of the planes that
// are active (eq. M.5). This checks that a face satisfying them was always found.
TEST(MohrCoulomb, KuhnTuckerConditionsHoldForAnyTrialState) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const Case& cs : cases) {
    const MohrCoulomb soil = make_soil(cs.phi, cs.psi, cs.cutoff);
    const auto& planes = soil.planes();
    for (int sample = 0; sample < 3000; ++sample) {
      const Vec3 stress = Vec3::Constant(-40 * (1 + u(rng))) + 60 * Vec3(u(rng), u(rng), u(rng));
      const Vec3 eps = sorted_descending(de.inverse() * stress);
      const Vec3 trial = de * eps;
      const PrincipalReturn r = soil.principal_return(eps, {});
      const double tol = 1e-9 * stress_scale(trial);
      for (const YieldPlane& p : planes) EXPECT_LE(p.normal.dot(r.stress) - p.limit, tol);
      const std::optional<Vec3> plastic_or_none = checked_plastic_strain(r, trial, de, tol);
      if (!plastic_or_none) continue;
      const Vec3& plastic = *plastic_or_none;
      Eigen::MatrixXd g(3, std::popcount(r.active));
      int j = 0;
      for (int k = 0; k < static_cast<int>(planes.size()); ++k)
        if (r.active & (1u << k)) {
          EXPECT_NEAR(planes[k].normal.dot(r.stress), planes[k].limit, tol);
          g.col(j++) = planes[k].flow;
        }
      const Eigen::VectorXd gamma = g.colPivHouseholderQr().solve(plastic);
      EXPECT_LT((g * gamma - plastic).norm(), 1e-9 * plastic.norm());
      EXPECT_GE(gamma.minCoeff(), -1e-9 * plastic.norm());
      EXPECT_LT((r.plastic_strain - plastic).norm(), 1e-9 * plastic.norm());
    }
  }
}

TEST(MohrCoulomb, TangentMatchesFiniteDifferencesInEveryRegion) {
  std::mt19937 rng(24);
  std::uniform_real_distribution<double> u(-1, 1);
  for (const Case& cs : cases) {
    const MohrCoulomb soil = make_soil(cs.phi, cs.psi, cs.cutoff);
    const Surface s(soil, cs.phi, cs.cutoff >= 0 ? cs.cutoff : soil.apex());
    std::vector<std::optional<Face>> regions = {std::nullopt};  // nullopt: elastic
    for (Face f : cs.faces) regions.push_back(f);
    for (const auto& region : regions)
      for (int sample = 0; sample < 12; ++sample) {
        Vec3 principal, returned;
        unsigned expected = 0;
        if (!region) {
          principal = de.inverse() * Vec3(-100 + 5 * u(rng), -100 + 5 * u(rng), -100 + 5 * u(rng));
          returned = de * sorted_descending(principal);
        } else {
          const FacePoint f = random_face_point(*region, s, rng);
          principal = trial_for(soil, f, rng);
          returned = f.stress;
          expected = f.expected;
        }
        const PrincipalReturn r = soil.principal_return(sorted_descending(principal), {});
        SCOPED_TRACE(::testing::Message()
                     << "phi " << cs.phi << " psi " << cs.psi << " cutoff " << cs.cutoff
                     << " region " << (region ? static_cast<int>(*region) : -1));
        // The region hit: its mask, or at a vertex where several masks are right, its stress.
        if (!region || expected != 0) {
          ASSERT_EQ(r.active, expected);
        }
        ASSERT_LT((r.stress - returned).norm(), 1e-10 * stress_scale(returned));
        const Mat3 eps = with_axes(principal, random_rotation(rng));
        StressUpdate out;
        soil.update(eps, {}, out);
        const Tensor4 fd = finite_difference_tangent(soil, eps, {}, 1e-8);
        EXPECT_LT(tangent_error(fd, out.tangent, elastic), 1e-6);
      }
  }
}

// A trial state exactly on a face (the stress of a converged plastic step, met again by a zero
// increment) keeps its stress; with `surface_tangent: plastic` its tangent is the plastic side's
// (docs/materials.md §1.7): the tangent (M.6) of the trial states beyond that face, which depends
// on the face only; by default the elastic one.
TEST(MohrCoulomb, OnTheSurfaceTheTangentIsThePlasticSidesWhenAskedFor) {
  std::mt19937 rng(27);
  for (const Case& cs : cases) {
    const MohrCoulomb soil = make_soil(cs.phi, cs.psi, cs.cutoff, SurfaceTangent::plastic);
    const MohrCoulomb by_default = make_soil(cs.phi, cs.psi, cs.cutoff);
    const Surface s(soil, cs.phi, cs.cutoff >= 0 ? cs.cutoff : soil.apex());
    for (Face face : cs.faces)
      for (int sample = 0; sample < 6; ++sample) {
        SCOPED_TRACE(::testing::Message() << "phi " << cs.phi << " psi " << cs.psi << " cutoff "
                                          << cs.cutoff << " face " << static_cast<int>(face));
        const FacePoint f = random_face_point(face, s, rng);
        const PrincipalReturn on =
            soil.principal_return(sorted_descending(de.inverse() * f.stress), yielded);
        const PrincipalReturn beyond =
            soil.principal_return(sorted_descending(trial_for(soil, f, rng)), yielded);
        EXPECT_NE(on.active, 0u);
        EXPECT_LT((on.stress - f.stress).norm(), 1e-10 * stress_scale(f.stress));
        EXPECT_EQ(on.plastic_strain, Vec3::Zero());
        EXPECT_LT((on.tangent - beyond.tangent).norm(), 1e-10 * de.norm());
        EXPECT_GT((on.tangent - de).norm(), 1e-2 * de.norm());
        // The whole update: the trial stress, with a tangent that is not the elastic one.
        StressUpdate out;
        const Mat3 eps = with_axes(de.inverse() * f.stress, random_rotation(rng));
        soil.update(eps, yielded, out);
        EXPECT_LT((out.kirchhoff - (lame_lambda(E, nu) * eps.trace() * Mat3::Identity() +
                                    2 * shear_modulus(E, nu) * eps))
                      .norm(),
                  1e-10 * stress_scale(f.stress));
        EXPECT_GT((out.tangent - elastic).norm(), 1e-2 * elastic.norm());
        by_default.update(eps, yielded, out);
        EXPECT_EQ(out.tangent, elastic);
        // A point that has never yielded reports the elastic side's tangent (§1.7).
        soil.update(eps, {}, out);
        EXPECT_EQ(out.tangent, elastic);
      }
  }
}

// Stress-free cohesionless soil sits at the apex of the cone, where every plane is at the surface
// and the plastic side's tangent is zero: with `surface_tangent: plastic` a point that has never
// yielded reports the elastic side's (docs/materials.md §1.7), so that the first step of a phase
// that loads such soil from rest has a regular tangent; once yielded at the apex, the zero one.
TEST(MohrCoulomb, StressFreeCohesionlessSoilKeepsTheElasticTangentUntilItYields) {
  const MohrCoulomb sand = make_mohr_coulomb(0.0, 30, 30, E, nu, -1, SurfaceTangent::plastic);
  StressUpdate out;
  sand.update(Mat3::Zero(), {}, out);
  EXPECT_EQ(out.kirchhoff, Mat3::Zero());
  EXPECT_EQ(out.tangent, elastic);
  sand.update(Mat3::Zero(), yielded, out);
  EXPECT_EQ(out.kirchhoff, Mat3::Zero());
  EXPECT_LT(out.tangent.norm(), 1e-12 * elastic.norm());
}

TEST(MohrCoulomb, ApexIsAFixedHydrostaticStressWithZeroTangent) {
  const MohrCoulomb soil = make_soil(30, 10);
  std::mt19937 rng(25);
  const Mat3 eps = with_axes(Vec3(0.01, 0.008, 0.005), random_rotation(rng));
  StressUpdate out;
  soil.update(eps, {}, out);
  EXPECT_LT((out.kirchhoff - soil.apex() * Mat3::Identity()).norm(), 1e-10 * soil.apex());
  EXPECT_LT(out.tangent.norm(), 1e-10 * elastic.norm());
  EXPECT_NEAR(soil.apex(), c * std::sqrt(3.0), 1e-12);
  EXPECT_GT(out.internal[MohrCoulomb::plastic_volumetric_strain_index], 0.0);
}

TEST(MohrCoulomb, StressRotatesWithTheTrialStrain) {
  for (const Case& cs : cases) {
    const MohrCoulomb soil = make_soil(cs.phi, cs.psi, cs.cutoff);
    std::mt19937 rng(26);
    std::uniform_real_distribution<double> u(-1, 1);
    for (int sample = 0; sample < 100; ++sample) {
      Mat3 a;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) a(i, j) = u(rng);
      const Mat3 eps = (a + a.transpose()) * 3e-3 - 2e-3 * (1 + u(rng)) * Mat3::Identity();
      StressUpdate out;
      soil.update(eps, {}, out);
      for (bool reflect : {false, true}) {
        const Mat3 rot = random_rotation(rng, reflect);
        StressUpdate turned;
        soil.update(rot * eps * rot.transpose(), {}, turned);
        EXPECT_LT((turned.kirchhoff - rot * out.kirchhoff * rot.transpose()).norm(),
                  1e-10 * (out.kirchhoff.norm() + c));
        EXPECT_LT((turned.elastic_strain - rot * out.elastic_strain * rot.transpose()).norm(),
                  1e-10 * out.elastic_strain.norm());
      }
    }
  }
}

}  // namespace
}  // namespace geompm
