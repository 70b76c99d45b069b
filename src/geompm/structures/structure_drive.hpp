// How a phase drives a rigid structure (docs/theory.md §17.4), per component of its motion (the
// step's unknowns of the structure: ux, uy, rotation about z in 2D; ux, uy, uz, rotations about
// x, y, z in 3D): a prescribed displacement (since the phase start) or velocity, as an
// expression of the phase time, makes the component a constrained unknown with its increment
// over the step; the other components are free, loaded by the given force or moment. In
// axisymmetry the radial translation and the rotation are always held at zero.
#pragma once

#include <optional>
#include <vector>

#include "geompm/core/expression.hpp"
#include "geompm/core/types.hpp"
#include "geompm/spec/model_spec.hpp"

namespace geompm {

/// The number of rigid-body unknowns for the kinematics: 3 in 2D (and axisymmetry), 6 in 3D.
int rigid_body_components(Kinematics kinematics);
/// The component of spec::StructureDrive (0-2 translations, 3-5 rotations about x, y, z) of the
/// rigid-body unknown k.
int drive_component(Kinematics kinematics, int k);

class StructureDrive {
 public:
  /// Free in every component (but those axisymmetry holds).
  explicit StructureDrive(Kinematics kinematics);
  StructureDrive(const spec::StructureDrive& drive, Kinematics kinematics);

  int components() const { return static_cast<int>(motion_.size()); }
  /// Component k is a constrained unknown of every step of the phase.
  bool prescribed(int k) const;
  /// Per component, its prescribed increment over [t0, t1] of the phase time (the displacement
  /// since the phase start at t1 minus at t0, or the velocity integrated by the trapezoidal rule,
  /// as for the point sets' motions); NaN for free components.
  std::vector<double> increment(double t0, double t1) const;
  /// Per component, the force (or moment) applied at phase time t; 0 where none is given.
  std::vector<double> load(double t) const;

 private:
  Kinematics kinematics_;
  bool velocity_ = false;
  std::vector<std::optional<Expression>> motion_, load_;
};

}  // namespace geompm
