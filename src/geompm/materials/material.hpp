// The material interface: a stress update and its algorithmic tangent, nothing else.
//
// Every material works in logarithmic (Hencky) strain and Kirchhoff stress (docs/theory.md §3):
// the kinematics (physics/finite_strain.hpp) forms the trial elastic strain
// eps_tr = 1/2 ln(b_e^tr), b_e^tr = dF b_e^n dF^T, and the material returns the Kirchhoff
// stress tau, the updated elastic strain and history, and the consistent tangent
// D = d tau / d eps_tr. The kinematics turns that into the spatial tangent of the updated
// Lagrangian Newton step, so a material knows nothing of grids, rotations or large strains:
// rotations are handled exactly (objectivity) and a small-strain return mapping carries over.
#pragma once

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "geompm/core/tensor.hpp"
#include "geompm/materials/internal_variables.hpp"

namespace geompm {

struct StressUpdate {
  Mat3 kirchhoff;       // tau = J sigma
  Mat3 elastic_strain;  // 1/2 ln(b_e) after the update (= eps_tr when elastic)
  InternalVariables internal{};
  Tensor4 tangent;  // d tau / d eps_tr, index (3i+j, 3k+l)
  // False if the update could not be computed (an iterative return that did not converge):
  // the point's state is then inadmissible and Newton cuts the step back.
  bool converged = true;
};

/// Elastic moduli of a point, for the mixed formulation's weights (docs/theory.md §11).
struct ElasticModuli {
  double bulk = 0.0;
  double shear = 0.0;
};

class Material {
 public:
  virtual ~Material() = default;

  virtual void update(const Mat3& trial_elastic_strain, const InternalVariables& internal_n,
                      StressUpdate& out) const = 0;

  /// Mass density in the reference state.
  virtual double density() const = 0;
  /// A Young's modulus that stands for the material's stiffness (empty-cell stiffness scale).
  virtual double reference_modulus() const = 0;
  /// The point's elastic bulk and shear moduli (its own values where they vary in space).
  virtual ElasticModuli elastic_moduli(const InternalVariables& internal) const = 0;
  /// Stored energy per unit reference volume at elastic strain eps (for energy histories).
  virtual double strain_energy(const Mat3& elastic_strain) const = 0;
  virtual const char* model_name() const = 0;

  /// Called by the engine once for each point when it is seeded (after MaterialPoints::add,
  /// before the first update), so that a material whose properties vary in space can store the
  /// point's own values in its internal variables (Tresca: s_u increasing with depth). The
  /// vertical coordinate is position(dimension - 1): y in 2D (plane strain, axisymmetry), z in 3D.
  /// The values then travel with the soil. May throw ParameterError (naming the parameter) when
  /// the point's values are out of range. Default: nothing to store.
  virtual void initialise_point(const Vec3& /*position*/, int /*dimension*/,
                                InternalVariables& /*internal*/) const {}
  /// How many internal variables the material uses: entries [0, count) of InternalVariables.
  virtual int internal_variable_count() const { return 0; }
  /// Name of internal variable k < internal_variable_count() for output ("su", ...).
  virtual const char* internal_variable_name(int /*k*/) const { return ""; }

  /// The elastic strain eps_e = 1/2 ln(b_e) at which the material's elastic law gives the
  /// Kirchhoff stress `kirchhoff` (with the point's `internal` variables, e.g. its own E): the
  /// inverse of the elastic law, used to start a point from a given stress (the K0 procedure,
  /// docs/theory.md §10), since a point stores b_e and its stress follows from it. Exact for the
  /// Hencky law of every current model. Whether that stress is admissible (inside a yield
  /// surface) is not checked here: update() at the returned strain tells. nullopt: the model
  /// cannot be started from a stress.
  virtual std::optional<Mat3> elastic_strain_for_stress(
      const Mat3& /*kirchhoff*/, const InternalVariables& /*internal*/) const {
    return std::nullopt;
  }
  /// The coefficient of earth pressure at rest the K0 procedure uses when the model file gives
  /// none (Mohr-Coulomb: Jaky's 1 - sin phi); nullopt: the model file must give it.
  virtual std::optional<double> default_k0() const { return std::nullopt; }
};

using ParameterMap = std::map<std::string, double>;

/// Creates the material registered as `model`. Throws ParameterError naming the offending key:
/// "model" for an unknown model, or the parameter that is missing, unknown or out of range.
std::unique_ptr<Material> create_material(const std::string& model, const ParameterMap& parameters);

/// Names of the registered material models.
std::vector<std::string> material_models();

}  // namespace geompm
