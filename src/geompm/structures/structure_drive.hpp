// How a phase drives a rigid structure (docs/theory.md §17.4), per component of its motion (the
// step's unknowns of the structure: ux, uy, rotation about z in 2D; ux, uy, uz, rotations about
// x, y, z in 3D): a prescribed displacement (since the phase start) or velocity, as an
// expression of the phase time, makes the component a constrained unknown with its increment
// over the step; the other components are free, loaded by the given force or moment. In
// axisymmetry the radial translation and the rotation are always held at zero.
//
// A deformable structure (§17.7) is driven on sets of its nodes instead: per set and component a
// prescribed displacement or velocity of each of its nodes, or a force shared equally by them;
// in axisymmetry its nodes on the axis are held radially.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "geompm/core/expression.hpp"
#include "geompm/core/linear_algebra.hpp"
#include "geompm/core/types.hpp"
#include "geompm/spec/model_spec.hpp"
#include "geompm/structures/structure_mesh.hpp"

namespace geompm {

/// A constrained unknown of a structure's field: entity (0 for a rigid structure, the node of a
/// deformable one), component and its increment over the step.
struct DriveConstraint {
  Index entity = 0;
  int component = 0;
  double value = 0.0;
};

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
  /// A deformable structure's: the phase's drives of it (each on a set of its nodes; none: free
  /// but for the axis in axisymmetry), on its mesh at the phase start.
  StructureDrive(const std::vector<const spec::StructureDrive*>& drives, const StructureMesh& mesh);

  /// Driven on nodes (a deformable structure).
  bool nodal() const { return nodal_; }
  /// The structure's unknowns prescribed over [t0, t1] of the phase time (for a rigid structure
  /// the components of increment(); for a deformable one the nodes' components, a later set
  /// winning over an earlier one at a node in both).
  std::vector<DriveConstraint> constraints(double t0, double t1) const;
  /// A deformable structure's nodal forces at phase time t, node-major (dim per node), on its
  /// free components.
  Vector nodal_load(double t, Index num_nodes) const;

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
  // The increment of `motion` over [t0, t1]: of a displacement, or a velocity's by the
  // trapezoidal rule.
  double increment_of(const Expression& motion, bool velocity, double t0, double t1) const;

  Kinematics kinematics_;
  bool velocity_ = false;
  std::vector<std::optional<Expression>> motion_, load_;
  // A deformable structure's sets of nodes and their drives.
  struct NodeSet {
    std::vector<Index> nodes;
    bool velocity = false;
    std::array<std::optional<Expression>, 3> motion, load;
  };
  bool nodal_ = false;
  int dim_ = 2;
  std::vector<NodeSet> sets_;
  std::vector<Index> axis_nodes_;  // axisymmetry: held radially
};

}  // namespace geompm
