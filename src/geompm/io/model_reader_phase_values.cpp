// The expressions of time a phase drives with (prescribed motions of points, nodes and
// structures, point-set loads) evaluated where `geompm check` can: at the phase's start and end.
// A non-finite value there ("log(t)" at t = 0, "1/(1-t)" at t = 1) is bad input, refused before
// any run; at the times between, the run itself stops with the same message (Expression).
#include <fmt/format.h>

#include "geompm/core/error.hpp"
#include "geompm/core/expression.hpp"
#include "geompm/io/model_reader_sections.hpp"

namespace geompm::model_reader {

namespace {

void check_at_ends(const std::string& text, const std::string& where, double duration) {
  if (text.empty()) return;  // a free component
  const Expression f(text, where);
  try {
    f.at_time(0.0);
    f.at_time(duration);
  } catch (const NonFiniteValue& e) {
    throw InputError(std::string(e.what()) + " (the phase's start or end)");
  }
}

template <class Item>
void check_components(const std::vector<Item>& items, double duration) {
  for (const Item& item : items)
    for (int d = 0; d < 3; ++d)
      check_at_ends(item.components[d], component_place(item.source, d), duration);
}

}  // namespace

void check_phase_expressions(const spec::Phase& phase) {
  const double duration = phase.duration;
  check_components(phase.motions, duration);
  check_components(phase.grid_motions, duration);
  check_components(phase.loads, duration);
  for (const spec::StructureDrive& drive : phase.structure_drives)
    for (int c = 0; c < 6; ++c) {
      const std::string where = fmt::format("{} (its {} {})", drive.source.describe(),
                                            c < 3 ? "translation" : "rotation", "xyz"[c % 3]);
      check_at_ends(drive.motion[c], where, duration);
      check_at_ends(drive.load[c], where, duration);
    }
}

}  // namespace geompm::model_reader
