#include "geompm/materials/tresca.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "geompm/core/error.hpp"
#include "geompm/materials/parameters.hpp"

namespace geompm {

namespace {

// Eq. M.9 in principal stresses sorted tau_1 >= tau_2 >= tau_3: the plane that bounds this
// sextant, tau_1 - tau_3 <= 2 s_u, and the two planes of the neighbouring sextants that meet it
// in the edges tau_2 = tau_3 (plane 1) and tau_1 = tau_2 (plane 2). Associated flow.
std::array<YieldPlane, 3> tresca_planes(double su) {
  const Vec3 n0(1, 0, -1), n1(1, -1, 0), n2(0, 1, -1);
  return {YieldPlane{n0, n0, 2 * su}, YieldPlane{n1, n1, 2 * su}, YieldPlane{n2, n2, 2 * su}};
}

// The faces of the prism in the order they are tried: the plane, then its two edges. The prism
// has no vertex.
constexpr std::array<unsigned, 3> tresca_faces = {Tresca::main_plane, Tresca::right_edge,
                                                  Tresca::left_edge};

}  // namespace

Tresca::Tresca(const Parameters& p) : p_(p) {}

std::unique_ptr<Material> Tresca::create(const ParameterMap& map) {
  ParameterReader r("tresca", map,
                    {"E", "E_over_su", "nu", "density", "su", "su_gradient", "su_reference_level",
                     "su_min", "surface_tangent"});
  Parameters p;
  const bool has_modulus = map.count("E") > 0, has_ratio = map.count("E_over_su") > 0;
  if (has_modulus == has_ratio)
    throw ParameterError("E",
                         "material model 'tresca' needs exactly one of 'E' (Young's modulus) "
                         "and 'E_over_su' (Young's modulus as a ratio to s_u)");
  if (has_modulus) p.youngs_modulus = ParameterReader::positive("E", r.required("E"));
  if (has_ratio)
    p.modulus_to_strength = ParameterReader::positive("E_over_su", r.required("E_over_su"));
  p.poisson_ratio = ParameterReader::poisson_ratio("nu", r.required("nu"));
  p.density = ParameterReader::non_negative("density", r.optional("density", 0));
  p.strength = ParameterReader::positive("su", r.required("su"));
  p.strength_gradient = r.optional("su_gradient", 0);
  if (p.strength_gradient != 0 && map.count("su_reference_level") == 0)
    throw ParameterError("su_reference_level",
                         "material model 'tresca' needs 'su_reference_level' (the vertical "
                         "coordinate where s_u = su) when 'su_gradient' is not zero");
  p.reference_level = r.optional("su_reference_level", 0);
  if (map.count("su_min"))
    p.minimum_strength = ParameterReader::positive("su_min", r.required("su_min"));
  p.surface_tangent = r.surface_tangent();
  return std::make_unique<Tresca>(p);
}

double Tresca::strength_at(double y) const {
  // Eq. M.11: depth is measured downward from the reference level.
  const double su = p_.strength + p_.strength_gradient * (p_.reference_level - y);
  return std::max(su, p_.minimum_strength);
}

void Tresca::initialise_point(const Vec3& position, int dimension,
                              InternalVariables& internal) const {
  const double y = position(dimension - 1);
  const double su = strength_at(y);
  if (!(su > 0))
    throw ParameterError(
        "su_min", fmt::format("material 'tresca': s_u = {:g} at the point at height {:g} "
                              "(su = {:g} at su_reference_level = {:g}, su_gradient = {:g}); "
                              "give a positive 'su_min'",
                              su, y, p_.strength, p_.reference_level, p_.strength_gradient));
  internal[strength_index] = su;
  internal[modulus_index] = p_.youngs_modulus > 0 ? p_.youngs_modulus : p_.modulus_to_strength * su;
}

const char* Tresca::internal_variable_name(int k) const {
  static constexpr const char* names[] = {"su", "youngs_modulus", "equivalent_plastic_strain"};
  return k >= 0 && k < 3 ? names[k] : "";
}

std::array<double, 2> Tresca::point_strength_and_modulus(const InternalVariables& internal) const {
  if (internal[strength_index] > 0 && internal[modulus_index] > 0)
    return {internal[strength_index], internal[modulus_index]};
  // A point the engine did not initialise: the reference-level soil (exact when su_gradient = 0).
  const double su = std::max(p_.strength, p_.minimum_strength);
  return {su, p_.youngs_modulus > 0 ? p_.youngs_modulus : p_.modulus_to_strength * su};
}

std::optional<Mat3> Tresca::elastic_strain_for_stress(const Mat3& kirchhoff,
                                                      const InternalVariables& internal) const {
  return hencky_strain(kirchhoff, point_strength_and_modulus(internal)[1], p_.poisson_ratio);
}

double Tresca::reference_modulus() const { return point_strength_and_modulus({})[1]; }

ElasticModuli Tresca::elastic_moduli(const InternalVariables& internal) const {
  const double E = point_strength_and_modulus(internal)[1], nu = p_.poisson_ratio;
  return {E / (3.0 * (1.0 - 2.0 * nu)), shear_modulus(E, nu)};
}

double Tresca::strain_energy(const Mat3& eps) const {
  const double E = reference_modulus();
  const double lambda = lame_lambda(E, p_.poisson_ratio), mu = shear_modulus(E, p_.poisson_ratio);
  const double tr = eps.trace();
  return 0.5 * lambda * tr * tr + mu * eps.squaredNorm();
}

PrincipalReturn Tresca::principal_return(const Vec3& trial_principal_strain,
                                         const InternalVariables& internal) const {
  const auto [su, E] = point_strength_and_modulus(internal);
  const Mat3 de =
      principal_elasticity(lame_lambda(E, p_.poisson_ratio), shear_modulus(E, p_.poisson_ratio));
  const auto planes = tresca_planes(su);
  return return_to_yield_planes(trial_principal_strain, de, planes, tresca_faces,
                                surface_side(p_.surface_tangent, internal[plastic_strain_index]));
}

void Tresca::update(const Mat3& eps, const InternalVariables& internal_n, StressUpdate& out) const {
  const auto [su, E] = point_strength_and_modulus(internal_n);
  out.internal = internal_n;
  out.internal[strength_index] = su;
  out.internal[modulus_index] = E;

  const SymmetricEigen trial = principal_descending(eps);
  const PrincipalReturn r = principal_return(trial.values, out.internal);
  if (r.active == 0) {
    // Elastic (docs/theory.md §3.3): the trial state, with its tangent in closed form.
    const double lambda = lame_lambda(E, p_.poisson_ratio), mu = shear_modulus(E, p_.poisson_ratio);
    out.kirchhoff = lambda * eps.trace() * Mat3::Identity() + 2.0 * mu * eps;
    out.elastic_strain = eps;
    out.tangent = isotropic_elasticity4(lambda, mu);
    return;
  }
  assemble_principal_update(trial, r, out);
  out.internal[plastic_strain_index] += equivalent_plastic_strain(r.plastic_strain);
}

}  // namespace geompm
