// Mohr-Coulomb: elastic-perfectly plastic soil in effective stress with a non-associated flow
// rule and a tension cut-off (model name "mohr_coulomb").
//
// In principal stresses sorted tau_1 >= tau_2 >= tau_3 (tension positive, so tau_3 is the most
// compressive) the yield function and the plastic potential are (docs/materials.md §3)
//   f = (tau_1 - tau_3) + (tau_1 + tau_3) sin(phi) - 2 c cos(phi),
//   g = (tau_1 - tau_3) + (tau_1 + tau_3) sin(psi),
// and the tension cut-off bounds every principal stress, tau_a <= t, with associated flow. The
// return is exact in principal stresses to every face of the surface: the main plane, the right
// edge tau_2 = tau_3 and the left edge tau_1 = tau_2 (dSPO §8.2), the apex, and the cut-off's own
// plane, edges and corners (docs/materials.md §3.3). The stress is the effective Kirchhoff stress
// (= Cauchy stress to within the elastic volume change); in a drained analysis it is the total
// stress.
//
// With `apex_rounding` a > 0 the surface is instead the smooth hyperbolic approximation of Abbo &
// Sloan (1995), apex and corners rounded (hyperbolic_surface.hpp), with a potential of the same
// form in psi, and the return is solved by Newton's method (hyperbolic_return.hpp,
// docs/materials.md §3.6).
#pragma once

#include <optional>
#include <vector>

#include "geompm/materials/hyperbolic_return.hpp"
#include "geompm/materials/material.hpp"
#include "geompm/materials/principal_return.hpp"

namespace geompm {

class MohrCoulomb final : public Material {
 public:
  struct Parameters {
    double cohesion = 0;
    double friction_angle = 0;  // degrees, 0 <= phi < 90
    double dilation_angle = 0;  // degrees, 0 <= psi <= phi
    double youngs_modulus = 0;
    double poisson_ratio = 0.3;
    double density = 0;
    double tension_cutoff = 0;  // largest principal stress, <= c / tan(phi)
    bool has_tension_cutoff = false;
    double apex_rounding = 0;     // a: the tip's offset from the cone's apex (stress); 0: sharp
    double lode_transition = 25;  // theta_T, degrees: the corners' rounding starts there
    SurfaceTangent surface_tangent = SurfaceTangent::elastic;  // docs/materials.md §1.7
  };

  // Internal variables (docs/materials.md §3.5).
  static constexpr int plastic_strain_index = 0;             // equivalent plastic strain (M.8)
  static constexpr int plastic_volumetric_strain_index = 1;  // tr eps_p, dilation positive

  // Planes of eq. M.12-M.13 (bit k of PrincipalReturn::active is plane k) and named faces.
  static constexpr unsigned main_plane = 0b000001;
  static constexpr unsigned right_edge = 0b000011;         // tau_2 = tau_3 (triaxial extension)
  static constexpr unsigned left_edge = 0b000101;          // tau_1 = tau_2 (triaxial compression)
  static constexpr unsigned tension_plane = 0b001000;      // tau_1 = t
  static constexpr unsigned main_tension_edge = 0b001001;  // tau_1 = t on the main plane
  static constexpr unsigned tension_edge = 0b011000;       // tau_1 = tau_2 = t
  static constexpr unsigned tension_corner = 0b111000;     // tau_1 = tau_2 = tau_3 = t

  explicit MohrCoulomb(const Parameters& p);
  static std::unique_ptr<Material> create(const ParameterMap& p);

  void update(const Mat3& trial_elastic_strain, const InternalVariables& internal_n,
              StressUpdate& out) const override;
  double density() const override { return p_.density; }
  double reference_modulus() const override { return p_.youngs_modulus; }
  ElasticModuli elastic_moduli(const InternalVariables&) const override {
    return {lambda_ + 2.0 * mu_ / 3.0, mu_};
  }
  double strain_energy(const Mat3& eps) const override;
  const char* model_name() const override { return "mohr_coulomb"; }
  int internal_variable_count() const override { return 2; }
  const char* internal_variable_name(int k) const override;
  std::optional<Mat3> elastic_strain_for_stress(const Mat3& kirchhoff,
                                                const InternalVariables& internal) const override;
  /// Jaky's K0 = 1 - sin(phi) for a normally consolidated soil.
  std::optional<double> default_k0() const override;

  /// The return in principal space for trial strains sorted eps_1 >= eps_2 >= eps_3: the core of
  /// update(), public so that tests can see the region. `internal`: the point's state at the
  /// start of the step (which side's tangent a state on the surface reports, §1.7).
  PrincipalReturn principal_return(const Vec3& trial_principal_strain,
                                   const InternalVariables& internal) const;

  /// The hydrostatic stress of the apex, c / tan(phi) (infinite for phi = 0); with a rounded
  /// apex, that of the sharp cone, a above the rounded surface's tip.
  double apex() const;
  const std::vector<YieldPlane>& planes() const { return planes_; }

 private:
  Parameters p_;
  double lambda_, mu_;
  Mat3 principal_elasticity_;
  Tensor4 elasticity_;
  std::vector<YieldPlane> planes_;
  // With a rounded apex: the hyperbolic surface and its potential (docs/materials.md §3.6).
  std::optional<HyperbolicSurface> yield_, potential_;
  std::vector<unsigned> faces_;  // the candidate active sets, in the order they are tried
};

}  // namespace geompm
