// Compressible neo-Hookean hyperelasticity (Bonet & Wood 2008, eq. 6.28):
// tau = mu (b - I) + lambda ln(J) I, written in eps = 1/2 ln(b) as
// tau = mu (exp(2 eps) - I) + lambda tr(eps) I. Model name "neo_hookean".
#pragma once

#include "geompm/materials/isotropic_elastic.hpp"

namespace geompm {

class NeoHookean final : public IsotropicElastic {
 public:
  NeoHookean(double youngs_modulus, double poisson_ratio, double density);
  static std::unique_ptr<Material> create(const ParameterMap& p);

  void update(const Mat3& trial_elastic_strain, const InternalVariables& internal_n,
              StressUpdate& out) const override;
  double strain_energy(const Mat3& eps) const override;
  const char* model_name() const override { return "neo_hookean"; }
  /// Newton on the principal values of tau_a = mu (exp(2 eps_a) - 1) + lambda sum_b eps_b, from
  /// the Hencky strain (the law is strictly monotone: a unique solution).
  std::optional<Mat3> elastic_strain_for_stress(const Mat3& kirchhoff,
                                                const InternalVariables& internal) const override;
};

}  // namespace geompm
