#include "geompm/materials/neo_hookean.hpp"

#include <Eigen/LU>
#include <cmath>

#include "geompm/materials/parameters.hpp"

namespace geompm {

NeoHookean::NeoHookean(double E, double nu, double density) : IsotropicElastic(E, nu, density) {}

void NeoHookean::update(const Mat3& eps, const InternalVariables& internal_n,
                        StressUpdate& out) const {
  const SymmetricEigen e = symmetric_eigen(eps);
  const auto exp2 = [](double x) { return std::exp(2.0 * x); };
  const Mat3 b = isotropic_function(e, exp2);
  out.kirchhoff = mu_ * (b - Mat3::Identity()) + lambda_ * eps.trace() * Mat3::Identity();
  out.elastic_strain = eps;
  out.internal = internal_n;
  // d tau / d eps = mu d exp(2 eps)/d eps + lambda I (x) I
  out.tangent = mu_ * isotropic_function_derivative(
                          e, exp2, [](double x) { return 2.0 * std::exp(2.0 * x); }) +
                lambda_ * identity_dyad_identity4();
}

double NeoHookean::strain_energy(const Mat3& eps) const {
  // W = mu/2 (tr b - 3) - mu ln J + lambda/2 (ln J)^2, ln J = tr eps
  const Mat3 b = symmetric_exp(2.0 * eps);
  const double lnJ = eps.trace();
  return 0.5 * mu_ * (b.trace() - 3.0) - mu_ * lnJ + 0.5 * lambda_ * lnJ * lnJ;
}

std::optional<Mat3> NeoHookean::elastic_strain_for_stress(const Mat3& kirchhoff,
                                                          const InternalVariables&) const {
  const SymmetricEigen t = symmetric_eigen(kirchhoff);
  const double scale = std::max(mu_, t.values.cwiseAbs().maxCoeff());
  Vec3 eps = (hencky_strain(t.values.asDiagonal().toDenseMatrix(), E_, nu_)).diagonal();
  for (int iteration = 0; iteration < 50; ++iteration) {
    Vec3 r;
    Mat3 jacobian = Mat3::Constant(lambda_);
    for (int a = 0; a < 3; ++a) {
      r(a) = mu_ * (std::exp(2 * eps(a)) - 1) + lambda_ * eps.sum() - t.values(a);
      jacobian(a, a) += 2 * mu_ * std::exp(2 * eps(a));
    }
    if (r.cwiseAbs().maxCoeff() <= 1e-13 * scale) break;
    eps -= jacobian.lu().solve(r);
  }
  return t.vectors * eps.asDiagonal() * t.vectors.transpose();
}

}  // namespace geompm
