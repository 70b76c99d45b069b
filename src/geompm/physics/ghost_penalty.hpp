// The ghost penalty of the body's edge cells (Burman 2010, C. R. Acad. Sci. Paris I 348; for the
// implicit MPM: Coombs 2023): the jump of the displacement's normal derivative across the faces
// of cells the body's edge runs through is penalised,
//   g(du, v) = sum_F gamma E_F h_F int_F [grad du . n] . [grad v . n] dF      (theory eq. 6.3),
// so that a node the points barely reach is held by the displacement field of its filled
// neighbours, extended across the face, rather than left nearly free. A field linear over both
// cells has no jump: the penalty does not resist a translation, a rotation or a uniform strain,
// unlike a spring at the node (eq. 6.2). Built once per step on the grid of the step, it acts on
// the step's displacement increment, like the empty-cell stiffness.
#pragma once

#include <span>
#include <vector>

#include "geompm/core/types.hpp"
#include "geompm/mesh/mesh.hpp"
#include "geompm/mesh/mesh_topology.hpp"
#include "geompm/physics/grid_system.hpp"
#include "geompm/physics/node_block.hpp"

namespace geompm {

/// What the penalty needs to know of each active cell of the step, as views of the caller's
/// arrays (indexed like `active_cells`; a cell that is not active holds no points). A cell holds
/// points exactly when its fill is above 0, since every point has a positive volume.
struct GhostPenaltyCells {
  std::span<const double> modulus;  // the largest Young's modulus of its points
  std::span<const double> fill;     // the fraction of its measure its points' volumes fill, <= 1
};

/// How much, and where: `gamma` scales the face's modulus; an edge cell counts only while its
/// fill is at most `fill_limit` (1: every edge cell); `radial` weights faces by r (axisymmetry,
/// per radian).
struct GhostPenaltySettings {
  double gamma = 0.0;
  double fill_limit = 0.5;
  bool radial = false;
};

/// The faces that carry the penalty, each a block over the nodes of its two cells. A face carries
/// it when both cells hold points and at least one of them is an edge cell: it shares a node with a
/// cell that holds none, and its points fill at most `fill_limit` of it. A well-filled cell on the
/// body's surface has nodes its points support well; where the body kinks for real beside it (the
/// fan at a footing's edge) the penalty would only stiffen it (docs/theory.md §6). gamma scales
/// E_F, the smaller of the two cells' moduli, so a stiff structure body does not stiffen the soil
/// beside it; h_F is the cells' mean size. Linear cells only: throws std::invalid_argument for
/// Tri6.
std::vector<NodeBlock> ghost_penalty_faces(const Mesh& mesh, const MeshTopology& topology,
                                           const std::vector<Index>& active_cells,
                                           const std::vector<Index>& node_to_active,
                                           const GhostPenaltyCells& cells,
                                           const GhostPenaltySettings& settings);

/// The faces of the step's grid that carry the penalty, with each edge cell's modulus the largest
/// Young's modulus E = 9 K G / (3 K + G) of its points (it varies in space where s_u does); none
/// when settings.ghost_penalty is 0.
std::vector<NodeBlock> ghost_penalty_blocks(const GridSystem& grid, const MaterialPoints& points);

}  // namespace geompm
