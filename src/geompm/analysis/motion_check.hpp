// Whether the points followed the motion prescribed to them. A prescribed motion of points is
// imposed by penalty springs (docs/theory.md §5): a body that cannot follow (a block squeezed to
// half its height, stiffening without bound) holds the springs stretched, and the run used to
// end "finished" with the points half-way. At the end of a phase, each motion's driven points are
// compared with what was prescribed; a shortfall stops the run instead.
//
// The comparison is of a mass-weighted mean per motion, so a distributed run needs sums only:
// each process sums its own driven points (motion_sums), the sums are added over the processes,
// and every process reads the same verdict from them (no point is gathered).
#pragma once

#include <string>
#include <vector>

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/phase_context.hpp"

namespace geompm {

/// The share of a prescribed displacement the points may fall short of, and the floor (of a
/// cell's size) below which a shortfall is the springs' own penalty error at any magnitude.
inline constexpr double motion_shortfall_tolerance = 0.01;
inline constexpr double motion_shortfall_floor = 1e-3;

/// Values motion_sums gives per prescribed motion: the weight, then the weighted displacement's
/// x, y, z.
inline constexpr std::size_t motion_sum_values = 4;

/// Per prescribed motion of `phase` (motion_sum_values each, in the phase's order), over the
/// points `model` holds that the motion drives: their weight (mass; volume if weightless) and
/// the weighted sum of their displacements since the phase start. Sums of several processes'
/// points add up.
std::vector<double> motion_sums(const Model& model, const PhaseContext& phase);

/// A description of each prescribed motion of `phase` whose points' mean displacement since the
/// phase start (mass-weighted, from `sums`: motion_sums over every point of the run) falls short
/// of the prescribed one in a component by more than the tolerance; empty if every motion was
/// followed.
std::string unfollowed_motions(const Model& model, const PhaseContext& phase,
                               const std::vector<double>& sums);

}  // namespace geompm
