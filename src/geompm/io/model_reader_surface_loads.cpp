// Model file key `surface_loads` of a phase: pressures and tractions on the soil's boundary, the
// zero level set of its points (docs/theory.md §16; docs/user-guide.md, "surface_loads").
#include <fmt/format.h>

#include <algorithm>

#include "geompm/io/model_reader_sections.hpp"

namespace geompm::model_reader {
namespace {

// `where: {x: [low, high], y: ...}`: a box on the axes given, the others unbounded.
void read_where(const yaml::Node& node, const Context& context, spec::SurfaceLoad& load) {
  const bool three_d = context.dimension == 3;
  const yaml::Map where = three_d ? node.map({"x", "y", "z"}) : node.map({"x", "y"});
  const char* names[] = {"x", "y", "z"};
  bool any = false;
  for (int axis = 0; axis < context.dimension; ++axis) {
    const auto range = where.find(names[axis]);
    if (!range) continue;
    const std::string expected =
        fmt::format("expected a range [low, high] along {}, e.g. [1, 5]", names[axis]);
    if (!range->is_list()) range->fail(fmt::format("{}; found {}", expected, range->describe()));
    const std::vector<yaml::Node> items = range->items();
    if (items.size() != 2)
      range->fail(fmt::format("{}; found a list of {} values", expected, items.size()));
    const std::array<double, 2> bounds = {items[0].number(), items[1].number()};
    if (!(bounds[0] < bounds[1]))
      range->fail(
          fmt::format("{}: low ({}) must be less than high ({})", expected, bounds[0], bounds[1]));
    load.where[axis] = bounds;
    any = true;
  }
  if (!any)
    node.fail(fmt::format("expected at least one range, such as {{x: [1, 5]}}; the axes are {}",
                          three_d ? "x, y, z" : "x, y"));
}

spec::SurfaceLoad read_surface_load(const yaml::Node& node, const Context& context) {
  const yaml::Map section = node.map({"pressure", "traction", "direction", "where", "bodies"});
  spec::SurfaceLoad load;
  load.source = node.where();
  std::vector<std::string> variables = {"x", "y", "t"};
  if (context.dimension == 3) variables.insert(variables.begin() + 2, "z");
  const std::string kind = section.exactly_one_of({"pressure", "traction"});
  load.pressure = kind == "pressure";
  if (load.pressure) {
    load.components[0] = read_expression(section.required("pressure"), variables);
  } else {
    load.components = read_expression_vector(section.required("traction"), context.dimension,
                                             variables, false, "0");
  }
  if (auto direction = section.find("direction")) {
    load.following = direction->choice({"fixed", "following"}) == "following";
    if (load.following && !load.pressure)
      direction->fail(
          "a traction keeps its direction: 'following' applies to a pressure, which turns and "
          "stretches with the surface (remove 'direction', or give a pressure)");
  }
  if (auto where = section.find_non_empty("where")) read_where(*where, context, load);
  if (auto bodies = section.find_non_empty("bodies"))
    for (const yaml::Node& item : bodies->items()) {
      const std::string body = read_reference(item, "body", context.bodies);
      if (std::find(load.bodies.begin(), load.bodies.end(), body) != load.bodies.end())
        item.fail(fmt::format("the body '{}' is listed twice", body));
      load.bodies.push_back(body);
    }
  return load;
}

}  // namespace

std::vector<spec::SurfaceLoad> read_surface_loads(const yaml::Node& node, const Context& context) {
  if (!node.is_list())
    node.fail(
        "expected a list of surface loads, such as - {pressure: 100, where: {x: [0, 2]}}; found " +
        node.describe());
  std::vector<spec::SurfaceLoad> loads;
  for (const yaml::Node& item : node.items()) loads.push_back(read_surface_load(item, context));
  return loads;
}

}  // namespace geompm::model_reader
