// Model file section `node_sets`: named groups of grid nodes chosen by a box, for fixities, grid
// motions (a smooth footing's base) and reaction histories, which name them like boundaries.
#include <fmt/format.h>

#include <algorithm>

#include "geompm/io/model_reader_sections.hpp"

namespace geompm::model_reader {

std::vector<spec::NodeSet> read_node_sets(const yaml::Node& node, Context& context) {
  std::vector<spec::NodeSet> node_sets;
  for (const auto& [name, set_node] : node.entries()) {
    if (name.empty()) set_node.fail("a node set needs a name");
    // A generated mesh's boundaries are known here; an imported mesh's are checked on import.
    if (std::find(context.boundaries.begin(), context.boundaries.end(), name) !=
        context.boundaries.end())
      set_node.fail(fmt::format(
          "'{}' is a boundary of the generated mesh already; give the node set another name",
          name));
    const yaml::Map entry = set_node.map({"box"});
    const yaml::Map box = entry.required("box").map({"min", "max"});
    spec::NodeSet set;
    set.name = name;
    set.source = set_node.where();
    set.min = box.required("min").vector(context.dimension);
    const yaml::Node max = box.required("max");
    set.max = max.vector(context.dimension);
    // min = max in a component is allowed: the nodes on a line or plane.
    for (int i = 0; i < context.dimension; ++i)
      if (set.min[i] > set.max[i])
        max.fail(
            fmt::format("a node set's box needs min <= max in every component; in {} min is "
                        "{} and max {}",
                        component_name(i), set.min[i], set.max[i]));
    context.node_sets.push_back(name);
    node_sets.push_back(std::move(set));
  }
  return node_sets;
}

}  // namespace geompm::model_reader
