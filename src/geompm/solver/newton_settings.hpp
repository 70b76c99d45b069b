// Newton's settings (the model file's `newton:` section of a phase, analysis/step.cpp), read by
// the loop (newton.cpp) and by its pieces: the convergence test, the backtracking and the energy
// line search.
#pragma once

#include "geompm/solver/forcing_term.hpp"

namespace geompm {

/// A residual this much smaller than the one before marks Newton's superlinear (quadratic) regime:
/// while points still switch between elastic and plastic the residual falls by factors of about
/// 1.5-6 an iteration (measured on the N_q strip of validation.md §9; up to 15 while only tens of
/// points switch on the stiff Tresca strip of §5, which the test counts as superlinear, harmlessly:
/// that start goes on), in the quadratic regime by far more (docs/theory.md §4.5).
inline constexpr double superlinear_contraction = 0.1;

/// The halvings of a grown residual's correction when a step that failed at the smallest allowed
/// step is tried once more (newton.line_search not set; analysis/simulation.cpp, docs/theory.md
/// §4.4): as many as an inadmissible iterate gets.
inline constexpr int fallback_halvings = 6;

struct NewtonSettings {
  int max_iterations = 15;
  /// If > 0: after this many iterations Newton goes on (up to max_iterations) only while it
  /// converges superlinearly, each residual below superlinear_contraction times the one before;
  /// a start that has not reached Newton's quadratic regime by then gives up early.
  int patience = 0;
  double residual_tolerance = 1e-8;
  double displacement_tolerance = 1e-8;
  /// The correction is judged relative to the larger of the step's increment and this norm
  /// (docs/theory.md eq. 4.5): the increment a full step would have (0: the step's own).
  double increment_floor = 0.0;
  double divergence_factor =
      1e8;  // residual growth over the first residual that counts as divergence
  /// Backtracking (backtracking.hpp): a correction that makes the residual grow is halved, at
  /// most this many times in a row (0: plain Newton, newton.line_search).
  int max_halvings = 0;
  /// ... and one that turns a point inside out, at most this many times (always on: an inverted
  /// iterate cannot be evaluated, and halving costs nothing where none inverts).
  int inadmissible_halvings = 6;
  /// Energy line search (docs/theory.md §4.4): if > 0, a correction dx after which the residual's
  /// component along it, s = dx . R, has turned negative beyond this fraction of its value at the
  /// start is shortened to where |s| is within this fraction (0: off).
  double energy_search = 0.0;
  /// Diagnostic: if > 0, each correction dx is checked against the residual's directional
  /// finite difference, (R(x + e dx) - R(x)) / e with e this value, which a consistent tangent
  /// K = -dR/dx matches to O(e): K dx = R(x). Costs one more residual evaluation an iteration.
  double tangent_check = 0.0;
  /// The relative residual to which an iterative linear solver solves K dx = R (a direct solver
  /// solves exactly and ignores it): well below the Newton tolerances, so that Newton's
  /// quadratic convergence is not lost to the linear solve.
  double linear_tolerance = 1e-10;
  /// Inexact Newton (forcing_term.hpp): an iterative solver's tolerance per iteration, from
  /// forcing.maximum down to linear_tolerance as Newton converges.
  ForcingSettings forcing;
};

}  // namespace geompm
