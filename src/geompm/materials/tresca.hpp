// Tresca: elastic-perfectly plastic undrained clay in total stress (model name "tresca").
//
// Yield when the largest principal stress difference reaches twice the undrained shear strength,
// tau_1 - tau_3 = 2 s_u, with associated (isochoric) flow: the hexagonal prism of
// docs/materials.md §2, returned to exactly in principal stresses (dSPO §8.1: the return to the
// main plane, to the right edge tau_2 = tau_3 or to the left edge tau_1 = tau_2).
//
// Yield is checked on the Kirchhoff stress tau = J sigma, which is what a material returns
// (docs/theory.md §3). Undrained flow is isochoric, J = 1, so there it is the Cauchy stress; in
// a compressible elastic range they differ by the (small) elastic volume change.
//
// s_u may increase linearly with depth below a reference level (a seabed: s_u = 2.3 + 3.6 z kPa
// in the seed's pipeline case), and the stiffness may be given as a ratio to s_u. Both are a
// property of the soil a point carries: initialise_point stores them in the point's internal
// variables when it is seeded, and they move with it.
#pragma once

#include <array>

#include "geompm/materials/material.hpp"
#include "geompm/materials/principal_return.hpp"

namespace geompm {

class Tresca final : public Material {
 public:
  struct Parameters {
    double youngs_modulus = 0;       // E; 0 when the stiffness is given as E_over_su
    double modulus_to_strength = 0;  // E / s_u; 0 when E is given
    double poisson_ratio = 0.49;
    double density = 0;
    double strength = 0;           // s_u at the reference level
    double strength_gradient = 0;  // d s_u / d depth
    double reference_level = 0;    // vertical coordinate where s_u = strength
    double minimum_strength = 0;   // floor of s_u; 0 for none
    SurfaceTangent surface_tangent = SurfaceTangent::elastic;  // docs/materials.md §1.7
  };

  // Internal variables (docs/materials.md §2.4).
  static constexpr int strength_index = 0;        // s_u of the point
  static constexpr int modulus_index = 1;         // Young's modulus of the point
  static constexpr int plastic_strain_index = 2;  // equivalent plastic strain (eq. M.8)

  // Return regions: bit k set when plane k of eq. M.9 is active.
  static constexpr unsigned main_plane = 0b001;
  static constexpr unsigned right_edge = 0b011;  // tau_2 = tau_3 (triaxial extension)
  static constexpr unsigned left_edge = 0b101;   // tau_1 = tau_2 (triaxial compression)

  explicit Tresca(const Parameters& p);
  static std::unique_ptr<Material> create(const ParameterMap& p);

  void update(const Mat3& trial_elastic_strain, const InternalVariables& internal_n,
              StressUpdate& out) const override;
  double density() const override { return p_.density; }
  /// The modulus at the reference level (at the su_min floor if that is higher).
  double reference_modulus() const override;
  /// With the point's own modulus.
  ElasticModuli elastic_moduli(const InternalVariables& internal) const override;
  /// Elastic energy with the reference-level modulus (the interface passes no point state).
  double strain_energy(const Mat3& eps) const override;
  const char* model_name() const override { return "tresca"; }

  /// Stores s_u and E at the point's height (eq. M.11). Throws ParameterError("su_min") when s_u
  /// would not be positive there.
  void initialise_point(const Vec3& position, int dimension,
                        InternalVariables& internal) const override;
  int internal_variable_count() const override { return 3; }
  const char* internal_variable_name(int k) const override;
  /// The Hencky inverse with the point's own E.
  std::optional<Mat3> elastic_strain_for_stress(const Mat3& kirchhoff,
                                                const InternalVariables& internal) const override;

  /// s_u at vertical coordinate y (eq. M.11), not yet checked for being positive.
  double strength_at(double y) const;

  /// The return in principal space for trial strains sorted eps_1 >= eps_2 >= eps_3, with the
  /// point's s_u and E: the core of update(), public so that tests can see the region.
  PrincipalReturn principal_return(const Vec3& trial_principal_strain,
                                   const InternalVariables& internal) const;

 private:
  // The point's s_u and E, or the reference-level values for a point that was never initialised.
  std::array<double, 2> point_strength_and_modulus(const InternalVariables& internal) const;

  Parameters p_;
};

}  // namespace geompm
