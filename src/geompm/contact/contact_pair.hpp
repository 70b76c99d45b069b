// A contact pair (docs/theory.md §18): a structure's surface against the soil's level set (the
// points of some bodies), with its tangential law. It lives for the whole analysis and carries
// from step to step what the next step starts from and what the output shows: each segment's
// multipliers (the contact pressure and shear over the scale c) and its state.
#pragma once

#include <array>
#include <string>
#include <vector>

#include "geompm/contact/contact_law.hpp"
#include "geompm/core/types.hpp"

namespace geompm {

class ByteWriter;
class ByteReader;

struct ContactPair {
  std::string name;     // the structure's name
  Index structure = 0;  // index into the model's structures
  /// Per body index: 1 if its points are the soil the structure touches (empty: all bodies).
  std::vector<char> bodies;
  ContactLaw law;
  bool enabled = true;  // false: the structure touches nothing (`contact: none`)
  /// Multiplies the automatic scale c = E / h (tests only: the results do not depend on it).
  double scale_factor = 1.0;

  /// Per contact segment (contact_segments' numbering), at the last converged step: the
  /// multipliers (length units: normal, then the tangential ones), the contact pressure and shear
  /// (stresses; shear along the segment's first tangent in 2D, its size in 3D), the state and
  /// whether the segment lay in the step's active cells.
  std::vector<std::array<double, 3>> multipliers;
  std::vector<double> pressure, shear;
  std::vector<ContactState> state;
  std::vector<char> in_grid;
  /// Per piece in the grid at the last converged step: its group's penetration, where the next
  /// step's starts if the piece touched (eq. 18.2; 0 when closed). An open piece is measured by
  /// the level set again, which places the soil's surface only to within a cell.
  std::vector<double> penetration;
  /// Per piece: the structure's surface facet it is part of, and its length or area.
  std::vector<Index> piece_facet;
  std::vector<double> piece_measure;
  /// The force the soil exerts on the structure through the contact, and its moment about the
  /// origin (z only in 2D), at the last converged step.
  Vec3 force = Vec3::Zero(), moment = Vec3::Zero();

  /// Per node of the structure's mesh (for ParaView): the contact pressure and shear, area-
  /// weighted over the pieces of the surface facets around it, and the state, the most engaged
  /// of theirs (0 open, 1 stick, 2 slip); zero away from the surface.
  void nodal_fields(const std::vector<std::array<Index, 4>>& facet_nodes,
                    const std::vector<int>& facet_node_count, Index num_nodes,
                    std::vector<double>& pressure, std::vector<double>& shear,
                    std::vector<Index>& state) const;

  void save(ByteWriter& out) const;
  void load(ByteReader& in);
};

}  // namespace geompm
