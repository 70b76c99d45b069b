// Reading material parameters with checks, so every material reports a bad value the same way.
#pragma once

#include <initializer_list>
#include <string>

#include "geompm/materials/material.hpp"
#include "geompm/materials/principal_return.hpp"

namespace geompm {

class ParameterReader {
 public:
  /// Throws ParameterError for any key of `p` that is not in `known`.
  ParameterReader(const std::string& model, const ParameterMap& p,
                  std::initializer_list<const char*> known);

  double required(const std::string& key) const;
  double optional(const std::string& key, double fallback) const;
  /// `surface_tangent` (docs/materials.md §1.7): 0 elastic (the default), 1 plastic; the model
  /// reader writes these for the words `elastic` and `plastic`.
  SurfaceTangent surface_tangent() const;

  /// Checks on a value just read; each throws ParameterError naming the key.
  static double positive(const std::string& key, double v);
  static double non_negative(const std::string& key, double v);
  static double poisson_ratio(const std::string& key, double v);  // -1 < nu < 0.5

 private:
  std::string model_;
  const ParameterMap& p_;
};

/// Lame parameters from Young's modulus and Poisson's ratio.
inline double lame_lambda(double E, double nu) { return E * nu / ((1 + nu) * (1 - 2 * nu)); }
inline double shear_modulus(double E, double nu) { return E / (2 * (1 + nu)); }

/// The inverse of the Hencky law tau = lambda tr(eps) I + 2 mu eps (docs/theory.md §3.3):
/// eps = ((1 + nu) tau - nu tr(tau) I) / E.
inline Mat3 hencky_strain(const Mat3& kirchhoff, double E, double nu) {
  return ((1 + nu) * kirchhoff - nu * kirchhoff.trace() * Mat3::Identity()) / E;
}

}  // namespace geompm
