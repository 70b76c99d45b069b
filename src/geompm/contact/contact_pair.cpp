#include "geompm/contact/contact_pair.hpp"

#include "geompm/core/byte_archive.hpp"

#include <algorithm>

namespace geompm {

void ContactPair::nodal_fields(const std::vector<std::array<Index, 4>>& facet_nodes,
                               const std::vector<int>& facet_node_count, Index num_nodes,
                               std::vector<double>& node_pressure, std::vector<double>& node_shear,
                               std::vector<Index>& node_state) const {
  node_pressure.assign(num_nodes, 0.0);
  node_shear.assign(num_nodes, 0.0);
  node_state.assign(num_nodes, 0);
  std::vector<double> weight(num_nodes, 0.0);
  for (std::size_t s = 0; s < piece_facet.size() && s < pressure.size(); ++s) {
    const Index f = piece_facet[s];
    if (f < 0 || f >= static_cast<Index>(facet_nodes.size())) continue;
    const int code = state[s] == ContactState::Open ? 0 : state[s] == ContactState::Stick ? 1 : 2;
    for (int a = 0; a < facet_node_count[f]; ++a) {
      const Index node = facet_nodes[f][a];
      node_pressure[node] += piece_measure[s] * pressure[s];
      node_shear[node] += piece_measure[s] * shear[s];
      weight[node] += piece_measure[s];
      node_state[node] = std::max<Index>(node_state[node], code);
    }
  }
  for (Index a = 0; a < num_nodes; ++a)
    if (weight[a] > 0.0) {
      node_pressure[a] /= weight[a];
      node_shear[a] /= weight[a];
    }
}

void ContactPair::save(ByteWriter& out) const {
  out.put(multipliers);
  out.put(pressure);
  out.put(shear);
  std::vector<int> states(state.size());
  for (std::size_t k = 0; k < state.size(); ++k) states[k] = static_cast<int>(state[k]);
  out.put(states);
  out.put(in_grid);
  out.put(piece_facet);
  out.put(piece_measure);
  out.put(force);
  out.put(moment);
  out.put(penetration);
}

void ContactPair::load(ByteReader& in) {
  in.get(multipliers);
  in.get(pressure);
  in.get(shear);
  std::vector<int> states;
  in.get(states);
  state.resize(states.size());
  for (std::size_t k = 0; k < states.size(); ++k) state[k] = static_cast<ContactState>(states[k]);
  in.get(in_grid);
  in.get(piece_facet);
  in.get(piece_measure);
  in.get(force);
  in.get(moment);
  in.get(penetration);
}

}  // namespace geompm
