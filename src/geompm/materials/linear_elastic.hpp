// Linear elasticity in logarithmic strain (Hencky): tau = lambda tr(eps) I + 2 mu eps, with
// eps = 1/2 ln(b). Hooke's law at small strain; exact under any rigid rotation (objective), and a
// hyperelastic law at large strain (docs/theory.md §3.3). Model name "linear_elastic"; the alias
// "hencky" names the same law.
#pragma once

#include "geompm/materials/isotropic_elastic.hpp"

namespace geompm {

class LinearElastic final : public IsotropicElastic {
 public:
  LinearElastic(double youngs_modulus, double poisson_ratio, double density);
  static std::unique_ptr<Material> create(const ParameterMap& p);

  void update(const Mat3& trial_elastic_strain, const InternalVariables& internal_n,
              StressUpdate& out) const override;
  double strain_energy(const Mat3& eps) const override;
  const char* model_name() const override { return "linear_elastic"; }
  std::optional<Mat3> elastic_strain_for_stress(const Mat3& kirchhoff,
                                                const InternalVariables& internal) const override;

 private:
  Tensor4 elasticity_;
};

}  // namespace geompm
