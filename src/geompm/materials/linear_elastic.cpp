#include "geompm/materials/linear_elastic.hpp"

#include "geompm/materials/parameters.hpp"

namespace geompm {

LinearElastic::LinearElastic(double E, double nu, double density)
    : IsotropicElastic(E, nu, density), elasticity_(isotropic_elasticity4(lambda_, mu_)) {}

void LinearElastic::update(const Mat3& eps, const InternalVariables& internal_n,
                           StressUpdate& out) const {
  out.kirchhoff = lambda_ * eps.trace() * Mat3::Identity() + 2.0 * mu_ * eps;
  out.elastic_strain = eps;
  out.internal = internal_n;
  out.tangent = elasticity_;
}

double LinearElastic::strain_energy(const Mat3& eps) const {
  const double tr = eps.trace();
  return 0.5 * lambda_ * tr * tr + mu_ * eps.squaredNorm();
}

std::optional<Mat3> LinearElastic::elastic_strain_for_stress(const Mat3& kirchhoff,
                                                             const InternalVariables&) const {
  return hencky_strain(kirchhoff, E_, nu_);
}

}  // namespace geompm
