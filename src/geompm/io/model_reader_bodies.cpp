// Model file sections `bodies` and `point_sets`, and the regions of space both use.
#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "geompm/io/model_reader_sections.hpp"
#include "geompm/points/seeding.hpp"

namespace geompm::model_reader {

namespace {

const char* region_forms(int dimension) {
  return dimension == 3 ? "'all', or a map with one of box, group, sphere"
                        : "'all', or a map with one of box, group, polygon, circle";
}

void read_box(const yaml::Node& node, int dimension, spec::Region& region) {
  const yaml::Map box = node.map({"min", "max"});
  region.min = box.required("min").vector(dimension);
  const yaml::Node max = box.required("max");
  region.max = max.vector(dimension);
  for (int i = 0; i < dimension; ++i)
    if (!(region.min[i] < region.max[i]))
      max.fail(fmt::format("a box needs min < max in every component; in {} min is {} and max {}",
                           component_name(i), region.min[i], region.max[i]));
}

void read_polygon(const yaml::Node& node, spec::Region& region) {
  const std::vector<yaml::Node> vertices = node.items();
  if (vertices.size() < 3)
    node.fail(fmt::format("a polygon needs at least 3 vertices [[x, y], ...], found {}",
                          vertices.size()));
  for (const yaml::Node& vertex : vertices) region.polygon.push_back(vertex.vector(2));
  // Shoelace area against the size of the bounding box: zero means the vertices are on a line.
  double twice_area = 0.0;
  Vec3 low = region.polygon[0], high = region.polygon[0];
  for (std::size_t i = 0; i < region.polygon.size(); ++i) {
    const Vec3& a = region.polygon[i];
    const Vec3& b = region.polygon[(i + 1) % region.polygon.size()];
    twice_area += a.x() * b.y() - b.x() * a.y();
    low = low.cwiseMin(a);
    high = high.cwiseMax(a);
  }
  const double extent = (high - low).norm();
  if (std::abs(twice_area) <= 1e-12 * extent * extent)
    node.fail("the polygon has no area (its vertices lie on a line)");
}

void read_round(const yaml::Node& node, int dimension, spec::Region& region) {
  const yaml::Map round = node.map({"center", "radius"});
  region.center = round.required("center").vector(dimension);
  region.radius = read_positive(round.required("radius"));
}

// The counts seeding can place (points/seeding.hpp). Before an imported mesh is read its cell
// type is unknown: accept a count that some cell type of the dimension allows, and let seeding
// check it against the actual type.
std::vector<int> points_per_cell_choices(std::optional<CellType> cell, int dimension) {
  if (cell) return allowed_points_per_cell(*cell);
  const std::vector<CellType> types =
      dimension == 3 ? std::vector{CellType::Tet4, CellType::Hex8, CellType::Pyramid5}
                     : std::vector{CellType::Tri3, CellType::Tri6, CellType::Quad4};
  std::vector<int> choices;
  for (CellType type : types)
    for (int count : allowed_points_per_cell(type))
      if (std::find(choices.begin(), choices.end(), count) == choices.end())
        choices.push_back(count);
  std::sort(choices.begin(), choices.end());
  return choices;
}

int read_points_per_cell(const yaml::Node& node, const Context& context) {
  const int count = node.integer();
  const std::vector<int> choices = points_per_cell_choices(context.cell_type, context.dimension);
  if (std::find(choices.begin(), choices.end(), count) == choices.end()) {
    const std::string cells = context.cell_type
                                  ? fmt::format("{} cells", to_string(*context.cell_type))
                                  : fmt::format("an imported {}D mesh", context.dimension);
    node.fail(fmt::format("points_per_cell for {} must be one of {}, found {}", cells,
                          fmt::join(choices, ", "), count));
  }
  return count;
}

// Layers by elevation, top down: every layer but the last has a bottom, below the one above.
std::vector<spec::Layer> read_layers(const yaml::Node& node, const Context& context) {
  const char* vertical = context.dimension == 3 ? "z" : "y";
  if (!node.is_list())
    node.fail(
        fmt::format("expected a list of layers, top down, such as [{{material: sand, bottom: "
                    "6}}, {{material: clay}}]; found {}",
                    node.describe()));
  const std::vector<yaml::Node> items = node.items();
  if (items.size() < 2)
    node.fail(fmt::format("expected at least 2 layers, found {} (one material: use 'material')",
                          items.size()));
  std::vector<spec::Layer> layers;
  for (std::size_t k = 0; k < items.size(); ++k) {
    const yaml::Map entry = items[k].map({"material", "bottom"});
    spec::Layer layer;
    layer.source = items[k].where();
    layer.material = read_reference(entry.required("material"), "material", context.materials);
    const bool last = k + 1 == items.size();
    if (last) {
      if (auto bottom = entry.find("bottom"))
        bottom->fail(
            "the last layer reaches down to the bottom of the body's region: remove its 'bottom'");
    } else {
      const yaml::Node bottom = entry.required("bottom");
      layer.bottom = bottom.number();
      if (!layers.empty() && !(*layer.bottom < *layers.back().bottom))
        bottom.fail(
            fmt::format("layers are listed top down: the bottom of this layer ({} = {}) "
                        "must lie below that of the layer above ({} = {})",
                        vertical, *layer.bottom, vertical, *layers.back().bottom));
    }
    layers.push_back(std::move(layer));
  }
  return layers;
}

}  // namespace

spec::Region read_region(const yaml::Node& node, const Context& context) {
  const int dim = context.dimension;
  spec::Region region;
  region.source = node.where();
  if (node.is_scalar()) {
    if (node.text() != "all")
      node.fail(fmt::format("expected {}; found {}", region_forms(dim), node.describe()));
    region.kind = spec::Region::Kind::All;
    return region;
  }
  if (!node.is_map())
    node.fail(fmt::format("expected {}; found {}", region_forms(dim), node.describe()));
  const yaml::Map forms = node.map({"box", "group", "polygon", "circle", "sphere"});
  const std::string form = forms.exactly_one_of({"box", "group", "polygon", "circle", "sphere"});
  const yaml::Node value = forms.required(form);
  if (form == "box") {
    region.kind = spec::Region::Kind::Box;
    read_box(value, dim, region);
  } else if (form == "group") {
    region.kind = spec::Region::Kind::Group;
    region.group = value.text();
    if (region.group.empty()) value.fail("expected the name of a cell group of the mesh");
  } else if (form == "polygon") {
    if (dim == 3) value.fail("a polygon is a 2D region; in 3D use box or sphere");
    region.kind = spec::Region::Kind::Polygon;
    read_polygon(value, region);
  } else if (form == "circle") {
    if (dim == 3) value.fail("a circle is a 2D region; in 3D use sphere");
    region.kind = spec::Region::Kind::Circle;
    read_round(value, dim, region);
  } else {
    if (dim == 2) value.fail("a sphere is a 3D region; in 2D use circle");
    region.kind = spec::Region::Kind::Circle;
    read_round(value, dim, region);
  }
  return region;
}

std::vector<spec::Body> read_bodies(const yaml::Node& node, Context& context) {
  const std::vector<std::string> velocity_variables = context.dimension == 3
                                                          ? std::vector<std::string>{"x", "y", "z"}
                                                          : std::vector<std::string>{"x", "y"};
  std::vector<spec::Body> bodies;
  for (const auto& [name, body_node] : node.entries()) {
    if (name.empty()) body_node.fail("a body needs a name");
    const yaml::Map entry = body_node.map(
        {"material", "layers", "region", "points_per_cell", "initial_velocity", "initial_stress"});
    spec::Body body;
    body.name = name;
    body.source = body_node.where();
    std::vector<std::string>& materials = context.body_materials[name];
    if (entry.has("layers")) {
      entry.exactly_one_of({"material", "layers"});
      body.layers = read_layers(entry.required("layers"), context);
      for (const spec::Layer& layer : body.layers) materials.push_back(layer.material);
    } else {
      body.material = read_reference(entry.required("material"), "material", context.materials);
      materials.push_back(body.material);
    }
    body.region = read_region(entry.required("region"), context);
    // Not given: the cell type's default; an imported mesh's types are known once it is read,
    // and a 3D one may mix tetrahedra (4) with hexahedra and pyramids (8).
    body.points_per_cell = context.cell_type ? default_points_per_cell(*context.cell_type) : 0;
    body.points_per_cell_source = body.source;
    body.points_per_cell_source.key_path += ".points_per_cell";
    if (auto count = entry.find("points_per_cell")) {
      body.points_per_cell = read_points_per_cell(*count, context);
      body.points_per_cell_source = count->where();
    }
    if (auto velocity = entry.find("initial_velocity"))
      body.initial_velocity =
          read_expression_vector(*velocity, context.dimension, velocity_variables, false, "0");
    if (auto stress = entry.find("initial_stress"))
      body.initial_stress = read_initial_stress(*stress, context);
    context.bodies.push_back(name);
    bodies.push_back(std::move(body));
  }
  if (bodies.empty())
    node.fail("expected at least one body, e.g. soil: {material: clay, region: all}");
  return bodies;
}

std::vector<spec::PointSet> read_point_sets(const yaml::Node& node, Context& context) {
  std::vector<spec::PointSet> point_sets;
  for (const auto& [name, set_node] : node.entries()) {
    if (name.empty()) set_node.fail("a point set needs a name");
    const yaml::Map entry = set_node.map({"body", "region"});
    spec::PointSet set;
    set.name = name;
    set.source = set_node.where();
    if (auto body = entry.find("body")) set.body = read_reference(*body, "body", context.bodies);
    set.region = read_region(entry.required("region"), context);
    context.point_sets.push_back(name);
    point_sets.push_back(std::move(set));
  }
  return point_sets;
}

}  // namespace geompm::model_reader
