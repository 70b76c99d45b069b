// What the isotropic elastic laws share: Young's modulus, Poisson's ratio, density and the Lame
// parameters, read and checked the same way for every model.
#pragma once

#include "geompm/materials/material.hpp"

namespace geompm {

class IsotropicElastic : public Material {
 public:
  IsotropicElastic(double youngs_modulus, double poisson_ratio, double density);

  double density() const override { return density_; }
  double reference_modulus() const override { return E_; }
  ElasticModuli elastic_moduli(const InternalVariables&) const override {
    return {lambda_ + 2.0 * mu_ / 3.0, mu_};
  }

 protected:
  /// Reads E (> 0), nu (in (-1, 0.5)) and density (>= 0, default 0) of `model`.
  template <class Law>
  static std::unique_ptr<Material> create_from(const char* model, const ParameterMap& p);

  double E_, nu_, density_, lambda_, mu_;
};

}  // namespace geompm
