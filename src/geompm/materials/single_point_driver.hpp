// A single-point driver for element tests: one material point taken along a path on which each
// of the six independent components of the strain (xx, yy, zz, xy, yz, zx) is either prescribed
// (strain control) or left free with its stress prescribed (stress control: stress-free, a
// confining pressure, a constant vertical stress). The free strains are found by Newton's method
// with the material's own tangent, so a test of the element also tests the tangent: with a
// consistent tangent a stress-controlled increment converges quadratically.
//
// The driver works in the material's variables (docs/theory.md §3): logarithmic strain and
// Kirchhoff stress. A strain increment is added to the elastic strain to form the trial strain,
// eps_tr = eps_e,n + d eps, which is the exponential-map predictor of eq. 3.2 for an increment
// without rotation whose principal axes stay those of b_e (triaxial and oedometric paths, exact
// at any strain); for a shear path the principal axes turn and it is the small-strain increment.
#pragma once

#include <array>
#include <vector>

#include "geompm/materials/material.hpp"

namespace geompm {

/// Components of a symmetric tensor in the order xx, yy, zz, xy, yz, zx (tensor components: the
/// engineering shear strain is gamma_xy = 2 eps_xy).
using Vec6 = Eigen::Matrix<double, 6, 1>;
Vec6 to_components(const Mat3& a);

enum class Control { strain, stress };

/// A straight segment of a loading path, applied in `increments` equal steps.
struct PathSegment {
  std::array<Control, 6> control{Control::strain, Control::strain, Control::strain,
                                 Control::strain, Control::strain, Control::strain};
  Vec6 strain_increment = Vec6::Zero();  // over the segment, for strain-controlled components
  Vec6 final_stress = Vec6::Zero();      // at its end, for stress-controlled components
  int increments = 1;
};

struct DriverState {
  Mat3 strain = Mat3::Zero();          // total strain: the sum of the increments
  Mat3 elastic_strain = Mat3::Zero();  // eps_e, the material's state
  Mat3 stress = Mat3::Zero();          // Kirchhoff, tension positive
  InternalVariables internal{};
  Tensor4 tangent = Tensor4::Zero();
  int iterations = 0;  // Newton iterations of the last increment (0: strain-controlled only)
};

class SinglePointDriver {
 public:
  /// Starts from zero strain and stress with the given internal variables (call the material's
  /// initialise_point on them first when it has any).
  explicit SinglePointDriver(const Material& material, const InternalVariables& internal = {});
  /// The driver keeps a reference to the material: a temporary would not outlive it.
  SinglePointDriver(const Material&& material, const InternalVariables& internal = {}) = delete;

  /// Applies a segment and returns the state after each of its increments. Throws RunError when
  /// Newton does not converge in an increment.
  std::vector<DriverState> follow(const PathSegment& segment);

  const DriverState& state() const { return state_; }

  double tolerance = 1e-10;  // on the stress residual, relative to the stresses in play
  int max_iterations = 30;

 private:
  // Updates the material at the trial strain eps_e,n + d eps into `out`.
  void evaluate(const Mat3& strain_increment, DriverState& out) const;

  const Material& material_;
  DriverState state_;
};

}  // namespace geompm
