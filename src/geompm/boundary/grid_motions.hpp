// Prescribed motion of grid nodes (docs/theory.md §5.3): the nodes of a boundary, node set or
// plane, resolved once per phase, with their motion as expressions of the phase time. The step
// imposes them as non-zero values of constrained unknowns.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "geompm/core/expression.hpp"
#include "geompm/mesh/mesh.hpp"
#include "geompm/spec/model_spec.hpp"

namespace geompm {

struct ResolvedGridMotion {
  std::string name;          // boundary or node set name, or "plane y=3"
  std::vector<Index> nodes;  // mesh nodes
  bool velocity = false;
  std::array<std::optional<Expression>, 3> components;  // empty = free

  /// The prescribed displacement increment over [t0, t1] of the phase, NaN for free components.
  Vec3 increment(double t0, double t1) const;
};

/// Throws InputError (at the motion's source) for a plane that holds no node, or for a node
/// that two motions of the list drive in the same component.
std::vector<ResolvedGridMotion> resolve_grid_motions(const Mesh& mesh,
                                                     const std::vector<spec::GridMotion>& motions);

/// The increment over [t0, t1] of a motion given per component by its displacement since the
/// phase start or its velocity (integrated with the trapezoidal rule, consistent with Newmark
/// gamma = 1/2); NaN for free components. Shared by point-set and grid motions.
Vec3 prescribed_increment(const std::array<std::optional<Expression>, 3>& components, bool velocity,
                          double t0, double t1);

}  // namespace geompm
