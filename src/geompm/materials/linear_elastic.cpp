#include "geompm/materials/linear_elastic.hpp"

#include "geompm/materials/parameters.hpp"

namespace geompm {

LinearElastic::LinearElastic(double E, double nu, double density)
    : E_(E), nu_(nu), density_(density), lambda_(lame_lambda(E, nu)), mu_(shear_modulus(E, nu)) {
  elasticity_ = isotropic_elasticity4(lambda_, mu_);
}

std::unique_ptr<Material> LinearElastic::create(const ParameterMap& p) {
  ParameterReader r("linear_elastic", p, {"E", "nu", "density"});
  return std::make_unique<LinearElastic>(ParameterReader::positive("E", r.required("E")),
                                         ParameterReader::poisson_ratio("nu", r.required("nu")),
                                         ParameterReader::non_negative("density",
                                                                       r.optional("density", 0)));
}

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

}  // namespace geompm
