// The soil's boundary as a level set (Brinkgreve et al. 2015, "Numerical modelling of
// large-deformation problems in geotechnical engineering with the implicit material point method",
// §3.3): the active domain is where the material points are, not where the grid is, so its
// boundary is found from the points at the start of each step as the zero level set of a nodal
// field phi that measures how much of each node's support the points fill (docs/theory.md §16,
// eq. 16.1). Surface loads (§3.5) and contact integrate over that zero level set.
#pragma once

#include <vector>

#include "geompm/physics/grid_system.hpp"

namespace geompm {

/// Density-based level set of the material points on the step's grid (seed §3.3): per active node
/// phi_I = m_I / (rho_I V_I) - 1/2, where m_I is the nodal mass of the selected bodies' points
/// (an FEM cell counts as filled: docs/theory.md §19.4),
/// rho_I their density at the node, V_I = integral of N_I over all mesh cells around the node.
/// Positive inside the body, 0 on its boundary, -1/2 far outside.
///
/// rho_I is the nodal mass over the nodal volume the points map, m_I / sum_p N_I V_p (the
/// volume-weighted mean of the points' densities), so m_I / rho_I is the share of the node's
/// support the points fill whatever their densities. A mass-weighted mean would give
/// m_I / rho_I = (1 + k)^2 / (2 (1 + k^2)) < 1 of the support inside a body at an interface
/// between densities 1 : k, and 1/2 (phi = 0: a false boundary) next to a massless body.
/// In axisymmetry the sums are per unit area of the meridian plane (each point's per-radian volume
/// divided by its radius; V_I without r), not per radian: with r in both, a vertical free surface
/// at radius R would have phi = -h / (6 R) rather than 0 at its nodes (cells of width h), and the
/// zero level set would move inward by up to h / 3 near the axis (docs/theory.md §16.1).
/// Horizontal surfaces are the same either way.
class LevelSet {
 public:
  /// After grid.initialise(points). `bodies`: per body index 1 if its points count (empty: all).
  LevelSet(const GridSystem& grid, const MaterialPoints& points, std::vector<char> bodies = {});
  const GridSystem& grid() const { return grid_; }
  /// phi per active node (grid.active_nodes() order).
  const std::vector<double>& nodal() const { return phi_; }
  /// phi at mesh node `node`: -1/2 at a node that is not active in the step.
  double node_value(Index node) const;
  /// phi at mesh cell `cell`, local coordinates xi (cell's shape functions; -1/2 at inactive
  /// nodes), and its spatial gradient there (start-of-step configuration).
  double value(Index cell, const Vec3& xi) const;
  Vec3 gradient(Index cell, const Vec3& xi) const;
  /// The value far outside the body (no point supports the node).
  static constexpr double outside = -0.5;

 private:
  const GridSystem& grid_;
  std::vector<double> phi_;
};

}  // namespace geompm
