#include "geompm/materials/mohr_coulomb.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "geompm/core/error.hpp"
#include "geompm/materials/parameters.hpp"

namespace geompm {

namespace {

double radians(double degrees) { return degrees * std::numbers::pi / 180.0; }

}  // namespace

MohrCoulomb::MohrCoulomb(const Parameters& p)
    : p_(p),
      lambda_(lame_lambda(p.youngs_modulus, p.poisson_ratio)),
      mu_(shear_modulus(p.youngs_modulus, p.poisson_ratio)) {
  principal_elasticity_ = principal_elasticity(lambda_, mu_);
  elasticity_ = isotropic_elasticity4(lambda_, mu_);

  // Eq. M.12: in the sextant tau_1 >= tau_2 >= tau_3, the main plane (0) and the planes of the
  // neighbouring sextants that meet it in the right edge tau_2 = tau_3 (1) and in the left edge
  // tau_1 = tau_2 (2). Normals from phi, flows from psi (non-associated).
  const double sf = std::sin(radians(p.friction_angle)), sd = std::sin(radians(p.dilation_angle));
  const double k = 2.0 * p.cohesion * std::cos(radians(p.friction_angle));
  planes_ = {
      {Vec3(1 + sf, 0, -(1 - sf)), Vec3(1 + sd, 0, -(1 - sd)), k},
      {Vec3(1 + sf, -(1 - sf), 0), Vec3(1 + sd, -(1 - sd), 0), k},
      {Vec3(0, 1 + sf, -(1 - sf)), Vec3(0, 1 + sd, -(1 - sd)), k},
  };
  // Eq. M.13: the tension cut-off, tau_a <= t for each principal stress, associated.
  if (p.has_tension_cutoff)
    for (int a = 0; a < 3; ++a) planes_.push_back({Vec3::Unit(a), Vec3::Unit(a), p.tension_cutoff});
  if (p.apex_rounding > 0) {
    // docs/materials.md §3.6: the smooth hyperbolic surface and its potential of the same form.
    yield_.emplace(p.friction_angle, p.cohesion, p.apex_rounding, p.lode_transition);
    potential_.emplace(p.dilation_angle, 0.0, p.apex_rounding, p.lode_transition);
  }
  // Planes first, then edges, then vertices (eq. M.5 picks the one face that satisfies the
  // Kuhn-Tucker conditions; the order only decides between equal answers on a region boundary).
  faces_ = active_sets_up_to_three(static_cast<int>(planes_.size()));
}

std::unique_ptr<Material> MohrCoulomb::create(const ParameterMap& map) {
  ParameterReader r("mohr_coulomb", map,
                    {"c", "phi", "psi", "E", "nu", "density", "tension_cutoff", "surface_tangent",
                     "apex_rounding", "lode_transition"});
  Parameters p;
  p.cohesion = ParameterReader::non_negative("c", r.required("c"));
  p.friction_angle = r.required("phi");
  if (!(p.friction_angle >= 0 && p.friction_angle < 90))
    throw ParameterError("phi", fmt::format("'phi' (friction angle, degrees) must lie in "
                                            "[0, 90), got {}",
                                            p.friction_angle));
  p.dilation_angle = r.optional("psi", 0);
  if (!(p.dilation_angle >= 0 && p.dilation_angle <= p.friction_angle))
    throw ParameterError("psi", fmt::format("'psi' (dilation angle, degrees) must lie in "
                                            "[0, phi] = [0, {}], got {}",
                                            p.friction_angle, p.dilation_angle));
  if (p.cohesion == 0 && p.friction_angle == 0)
    throw ParameterError("c",
                         "material model 'mohr_coulomb' has no strength with c = 0 and "
                         "phi = 0");
  p.youngs_modulus = ParameterReader::positive("E", r.required("E"));
  p.poisson_ratio = ParameterReader::poisson_ratio("nu", r.required("nu"));
  p.density = ParameterReader::non_negative("density", r.optional("density", 0));
  p.surface_tangent = r.surface_tangent();

  const double apex = p.friction_angle > 0 ? p.cohesion / std::tan(radians(p.friction_angle))
                                           : std::numeric_limits<double>::infinity();
  if (map.count("apex_rounding")) {
    p.apex_rounding = ParameterReader::positive("apex_rounding", r.required("apex_rounding"));
    // docs/materials.md §3.6: the rounded surface's tip, c / tan(phi) - a, must lie in tension so
    // that stress-free soil is inside it; with psi = 0 the potential has no volumetric part to
    // bring a state in hydrostatic tension back to the tip.
    if (!(p.friction_angle > 0 && p.apex_rounding < apex))
      throw ParameterError("apex_rounding",
                           fmt::format("'apex_rounding' must be below the apex of the "
                                       "Mohr-Coulomb surface, c / tan(phi) = {:g} (phi > 0), so "
                                       "that stress-free soil lies inside the rounded surface; "
                                       "got {:g}",
                                       apex, p.apex_rounding));
    p.lode_transition = r.optional("lode_transition", p.lode_transition);
    if (!(p.lode_transition > 0 && p.lode_transition < 30))
      throw ParameterError("lode_transition",
                           fmt::format("'lode_transition' (degrees, where the rounding of the "
                                       "corners starts) must lie in (0, 30), got {}",
                                       p.lode_transition));
    if (!(p.dilation_angle > 0))
      throw ParameterError("apex_rounding",
                           "'apex_rounding' needs a dilation angle 'psi' > 0: with psi = 0 the "
                           "plastic flow cannot change the volume, and a state in hydrostatic "
                           "tension has no return to the rounded apex");
  } else if (map.count("lode_transition")) {
    throw ParameterError("lode_transition",
                         "'lode_transition' is a parameter of the rounded surface: give "
                         "'apex_rounding' too");
  }
  if (map.count("tension_cutoff")) {
    if (p.apex_rounding > 0)
      throw ParameterError("tension_cutoff",
                           "'tension_cutoff' cannot be combined with 'apex_rounding': the "
                           "rounded surface is one smooth surface, without cut-off planes");
    p.tension_cutoff =
        ParameterReader::non_negative("tension_cutoff", r.required("tension_cutoff"));
    if (p.tension_cutoff > apex * (1 + 1e-12))
      throw ParameterError("tension_cutoff",
                           fmt::format("'tension_cutoff' must not exceed the apex of the "
                                       "Mohr-Coulomb surface, c / tan(phi) = {:g}; got {:g}",
                                       apex, p.tension_cutoff));
    p.tension_cutoff = std::min(p.tension_cutoff, apex);
    p.has_tension_cutoff = true;
  } else if (p.friction_angle > 0 && p.apex_rounding == 0) {
    // At the apex the cut-off only adds flow directions there: the apex return of dSPO §8.2 for
    // any psi, including psi = 0, whose own flow directions cannot change the volume. (A rounded
    // surface lies inside the cone, below tau_1 = c / tan(phi): a cut-off there is never met.)
    p.tension_cutoff = apex;
    p.has_tension_cutoff = true;
  }
  return std::make_unique<MohrCoulomb>(p);
}

double MohrCoulomb::apex() const {
  return p_.friction_angle > 0 ? p_.cohesion / std::tan(radians(p_.friction_angle))
                               : std::numeric_limits<double>::infinity();
}

const char* MohrCoulomb::internal_variable_name(int k) const {
  static constexpr const char* names[] = {"equivalent_plastic_strain", "plastic_volumetric_strain"};
  return k >= 0 && k < 2 ? names[k] : "";
}

std::optional<Mat3> MohrCoulomb::elastic_strain_for_stress(const Mat3& kirchhoff,
                                                           const InternalVariables&) const {
  return hencky_strain(kirchhoff, p_.youngs_modulus, p_.poisson_ratio);
}

std::optional<double> MohrCoulomb::default_k0() const {
  return 1.0 - std::sin(radians(p_.friction_angle));
}

double MohrCoulomb::strain_energy(const Mat3& eps) const {
  const double tr = eps.trace();
  return 0.5 * lambda_ * tr * tr + mu_ * eps.squaredNorm();
}

PrincipalReturn MohrCoulomb::principal_return(const Vec3& trial_principal_strain,
                                              const InternalVariables& internal) const {
  const SurfaceTangent side = surface_side(p_.surface_tangent, internal[plastic_strain_index]);
  if (yield_)
    return return_to_hyperbolic_surface(trial_principal_strain, principal_elasticity_, *yield_,
                                        *potential_, side);
  return return_to_yield_planes(trial_principal_strain, principal_elasticity_, planes_, faces_,
                                side);
}

void MohrCoulomb::update(const Mat3& eps, const InternalVariables& internal_n,
                         StressUpdate& out) const {
  out.internal = internal_n;
  const SymmetricEigen trial = principal_descending(eps);
  const PrincipalReturn r = principal_return(trial.values, internal_n);
  out.converged = r.converged;
  if (r.active == 0) {
    // Elastic (docs/theory.md §3.3): the trial state, with its tangent in closed form.
    out.kirchhoff = lambda_ * eps.trace() * Mat3::Identity() + 2.0 * mu_ * eps;
    out.elastic_strain = eps;
    out.tangent = elasticity_;
    return;
  }
  assemble_principal_update(trial, r, out);
  out.internal[plastic_strain_index] += equivalent_plastic_strain(r.plastic_strain);
  out.internal[plastic_volumetric_strain_index] += r.plastic_strain.sum();
}

}  // namespace geompm
