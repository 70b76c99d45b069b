#include "geompm/contact/contact_pair.hpp"

#include "geompm/core/byte_archive.hpp"

namespace geompm {

void ContactPair::save(ByteWriter& out) const {
  out.put(multipliers);
  out.put(pressure);
  out.put(shear);
  std::vector<int> states(state.size());
  for (std::size_t k = 0; k < state.size(); ++k) states[k] = static_cast<int>(state[k]);
  out.put(states);
  out.put(in_grid);
  out.put(force);
  out.put(moment);
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
  in.get(force);
  in.get(moment);
}

}  // namespace geompm
