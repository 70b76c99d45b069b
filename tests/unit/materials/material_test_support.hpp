// Helpers shared by the material tests: random rotations, finite-difference tangents, and trial
// strains built from a chosen returned stress (so that the region of a trial state is known).
#pragma once

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <optional>
#include <random>

#include "geompm/materials/material.hpp"
#include "geompm/materials/mohr_coulomb.hpp"
#include "geompm/materials/principal_return.hpp"

namespace geompm::test_support {

/// The parameters every Mohr-Coulomb soil of the tests shares.
inline MohrCoulomb::Parameters mohr_coulomb_parameters(double c, double phi, double psi, double E,
                                                       double nu, SurfaceTangent surface) {
  MohrCoulomb::Parameters p;
  p.surface_tangent = surface;
  p.cohesion = c;
  p.friction_angle = phi;
  p.dilation_angle = psi;
  p.youngs_modulus = E;
  p.poisson_ratio = nu;
  return p;
}

/// A Mohr-Coulomb soil; the tension cut-off is `cutoff` when given (>= 0), otherwise at the apex
/// c / tan(phi) (none for phi = 0).
inline MohrCoulomb make_mohr_coulomb(double c, double phi, double psi, double E, double nu,
                                     double cutoff = -1,
                                     SurfaceTangent surface = SurfaceTangent::elastic) {
  MohrCoulomb::Parameters p = mohr_coulomb_parameters(c, phi, psi, E, nu, surface);
  const double apex = phi > 0 ? c / std::tan(phi * M_PI / 180) : 0;
  if (phi > 0 || cutoff >= 0) {
    p.has_tension_cutoff = true;
    p.tension_cutoff = cutoff >= 0 ? cutoff : apex;
  }
  return MohrCoulomb(p);
}

/// A Mohr-Coulomb soil with the rounded surface (docs/materials.md §3.6): apex rounding a, the
/// corners from `transition` degrees.
inline MohrCoulomb make_rounded_mohr_coulomb(double c, double phi, double psi, double E, double nu,
                                             double a, double transition = 25,
                                             SurfaceTangent surface = SurfaceTangent::elastic) {
  MohrCoulomb::Parameters p = mohr_coulomb_parameters(c, phi, psi, E, nu, surface);
  p.apex_rounding = a;
  p.lode_transition = transition;
  return MohrCoulomb(p);
}

/// A uniformly random rotation (det +1), or with `reflect` an improper one (det -1).
inline Mat3 random_rotation(std::mt19937& rng, bool reflect = false) {
  std::normal_distribution<double> n(0.0, 1.0);
  const Eigen::Quaterniond q(n(rng), n(rng), n(rng), n(rng));
  Mat3 r = q.normalized().toRotationMatrix();
  if (reflect) r.col(0) *= -1.0;
  return r;
}

/// The tensor with principal values `principal` on the axes of `rotation`.
inline Mat3 with_axes(const Vec3& principal, const Mat3& rotation) {
  return rotation * principal.asDiagonal() * rotation.transpose();
}

/// Central finite difference of update() with respect to the trial strain: column (3k+l) is
/// d tau / d eps for the symmetric increment (e_k e_l + e_l e_k) / 2, so that it compares with
/// a tangent that is symmetric in kl.
inline Tensor4 finite_difference_tangent(const Material& m, const Mat3& eps,
                                         const InternalVariables& internal, double h) {
  Tensor4 d;
  StressUpdate plus, minus;
  for (int k = 0; k < 3; ++k)
    for (int l = 0; l < 3; ++l) {
      Mat3 e = Mat3::Zero();
      e(k, l) += 0.5 * h;
      e(l, k) += 0.5 * h;
      m.update(eps + e, internal, plus);
      m.update(eps - e, internal, minus);
      d.col(pair_index(k, l)) = flatten(plus.kirchhoff - minus.kirchhoff) / (2 * h);
    }
  return d;
}

/// ||D_fd - D|| / ||D||, or relative to `reference` (the elastic tangent) where D vanishes (at a
/// vertex of the yield surface the stress is fixed and D = 0).
inline double tangent_error(const Tensor4& fd, const Tensor4& d, const Tensor4& reference) {
  const double norm = d.norm() > 1e-6 * reference.norm() ? d.norm() : reference.norm();
  return (fd - d).norm() / norm;
}

/// Principal trial strains whose return is the principal stress `returned`, reached through the
/// flows of `planes` (bit k of `mask`) with the multipliers `gamma`: by eq. M.4 read backwards,
/// eps_tr = (D^e)^-1 (tau + D^e sum_j gamma_j g_j).
inline Vec3 trial_strain_for(const Vec3& returned, const Mat3& de,
                             const std::vector<YieldPlane>& planes, unsigned mask,
                             const std::vector<double>& gamma) {
  Vec3 eps = de.inverse() * returned;
  int j = 0;
  for (int k = 0; k < static_cast<int>(planes.size()); ++k)
    if (mask & (1u << k)) eps += gamma.at(j++) * planes[k].flow;
  return eps;
}

/// The checks every principal return must pass: the returned stresses keep the order
/// tau_1 >= tau_2 >= tau_3 (to `tol`), and an elastic return (active 0) carries no plastic strain.
/// Returns the plastic strain D^-1 (tau_tr - tau) of a plastic return, nullopt for an elastic one.
inline std::optional<Vec3> checked_plastic_strain(const PrincipalReturn& r, const Vec3& trial,
                                                  const Mat3& de, double tol) {
  EXPECT_GE(r.stress(0), r.stress(1) - tol);
  EXPECT_GE(r.stress(1), r.stress(2) - tol);
  const Vec3 plastic = de.inverse() * (trial - r.stress);
  if (r.active != 0) return plastic;
  EXPECT_LT(plastic.norm(), 1e-14);
  return std::nullopt;
}

/// The principal values of eps sorted descending (the input order of principal_return).
inline Vec3 sorted_descending(Vec3 v) {
  std::sort(v.data(), v.data() + 3, [](double a, double b) { return a > b; });
  return v;
}

}  // namespace geompm::test_support
