// GIMP weights (generalized interpolation material point method, Bardenhagen & Kober 2004) on a
// rectilinear grid with non-uniform spacing, docs/theory.md §9: the nodal hat functions
// averaged over each point's particle domain, an axis-aligned box that follows the deformation
// (cpGIMP). The weights are tensor products of 1D weights along the grid lines; a point's
// stencil holds the nodes of every cell its domain overlaps (up to 3^dim for a domain no longer
// than the cells).
#pragma once

#include <array>
#include <vector>

#include "geompm/core/types.hpp"
#include "geompm/mesh/rectilinear_grid.hpp"

namespace geompm {

/// The weights of the nodes along one axis for one particle domain [centre - half, centre + half].
struct AxisWeights {
  int first = 0;          // grid index of the first node with a weight
  std::vector<double> S;  // weight of nodes first, first + 1, ... (theory eq. 9.2)
  std::vector<double> G;  // its gradient (theory eq. 9.3)
};

/// The domain's half-length along one axis, shrunk symmetrically about the centre so that the
/// domain stays within [lo, hi] (theory eq. 9.5; never negative).
double clip_half_length(double centre, double half, double lo, double hi);

/// 1D GIMP weights and gradients on grid lines `lines` (ascending) for the domain
/// [centre - half, centre + half], which must lie within the lines (clip first). `cell` is the
/// cell (between lines cell and cell + 1) holding the centre: for a domain of zero length the
/// weights fall back to the standard hat functions of that cell, their limit.
void gimp_axis_weights(const std::vector<double>& lines, double centre, double half, int cell,
                       AxisWeights& out);

/// cpGIMP half-lengths (theory eq. 9.4): the seeded half-lengths stretched by the diagonal of
/// the deformation gradient along the grid axes, l_d = l0_d max(F_dd, 0).
Vec3 particle_half_lengths(const Vec3& initial, const Mat3& F, int dim);

/// One point's GIMP stencil (theory eq. 9.1): mesh node ids in ascending order, weights N and
/// gradients (dim per node, row-major), and the range of cell indices its domain overlaps.
struct GimpStencil {
  std::vector<Index> nodes;
  std::vector<double> N;
  std::vector<double> gradients;
  std::array<int, 3> first_cell{0, 0, 0}, last_cell{0, 0, 0};  // inclusive, per axis
};

/// The stencil of a point at `centre` in mesh cell `cell`, with domain half-lengths `half`
/// (before clipping). The domain is clipped to the grid, and in axisymmetry to r >= 0, so that
/// the hoop term N / r never sees a domain across the axis.
void gimp_stencil(const RectilinearGrid& grid, const Vec3& centre, const Vec3& half, Index cell,
                  bool axisymmetric, GimpStencil& out);

}  // namespace geompm
