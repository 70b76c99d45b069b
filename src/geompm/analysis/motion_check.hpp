// Whether the points followed the motion prescribed to them. A prescribed motion of points is
// imposed by penalty springs (docs/theory.md §5): a body that cannot follow (a block squeezed to
// half its height, stiffening without bound) holds the springs stretched, and the run used to
// end "finished" with the points half-way. At the end of a phase, each motion's driven points are
// compared with what was prescribed; a shortfall stops the run instead.
#pragma once

#include <string>

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/phase_context.hpp"

namespace geompm {

/// The share of a prescribed displacement the points may fall short of, and the floor (of a
/// cell's size) below which a shortfall is the springs' own penalty error at any magnitude.
inline constexpr double motion_shortfall_tolerance = 0.01;
inline constexpr double motion_shortfall_floor = 1e-3;

/// A description of each prescribed motion of `phase` whose points' mean displacement since the
/// phase start (mass-weighted) falls short of the prescribed one in a component by more than
/// the tolerance; empty if every motion was followed.
std::string unfollowed_motions(const Model& model, const PhaseContext& phase);

}  // namespace geompm
