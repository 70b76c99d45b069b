// Model file: the top-level `structures` (docs/user-guide.md, "structures"): each a built-in
// shape or a Gmsh mesh, rigid, with its density, mass or weight and its reference point; a
// phase's `structures` map, how the phase drives each (per component: a prescribed displacement
// or velocity, or free with a force or moment); and the histories of a structure.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>
#include <map>

#include "geompm/io/input_file.hpp"
#include "geompm/io/model_reader_sections.hpp"

namespace geompm::model_reader {

namespace {

const std::vector<std::string> time_only = {"t"};

// The dimensions each shape takes: required, then optional (docs/user-guide.md).
struct ShapeKeys {
  std::vector<std::string> required, optional;
};

const std::map<std::string, ShapeKeys>& shape_keys() {
  static const std::map<std::string, ShapeKeys> keys = {
      {"pipe", {{"diameter"}, {"thickness", "length"}}},
      {"tbar", {{"diameter"}, {"length"}}},
      {"spudcan",
       {{"diameter", "tip_angle"}, {"shoulder", "top_angle", "shaft_diameter", "shaft_length"}}},
      {"plate", {{"width", "length"}, {"tip", "breadth"}}},
      {"cone", {{"diameter", "shaft_length"}, {"apex_angle"}}},
      {"footing", {{"width", "height"}, {"breadth"}}}};
  return keys;
}

bool is_angle(const std::string& key) { return key.ends_with("angle"); }

// The shape's dimensions: only those it takes, the required ones present, lengths >= 0 (> 0 where
// required), angles in (0, 180]; a 3D bar its length and a 3D plate its breadth, which 2D
// sections do not have.
void read_dimensions(const yaml::Node& node, const yaml::Map& section, const Context& context,
                     spec::StructureShape& shape) {
  const ShapeKeys& keys = shape_keys().at(shape.kind);
  std::vector<std::string> takes(keys.required);
  takes.insert(takes.end(), keys.optional.begin(), keys.optional.end());
  for (const auto& [key, value] : node.entries()) {
    if (key == "type" || key == "position" || key == "cell" || key == "cell_size") continue;
    if (std::find(takes.begin(), takes.end(), key) == takes.end())
      value.fail(fmt::format("a {} takes no '{}'; its dimensions are: {}", shape.kind, key,
                             yaml::join(takes)));
    const double v = is_angle(key) ? read_positive(value) : read_non_negative(value);
    if (is_angle(key) && v > 180)
      value.fail(
          fmt::format("expected an included angle in degrees, at most 180 (flat), found {}", v));
    shape.dimensions[key] = v;
  }
  for (const std::string& key : keys.required)
    shape.dimensions[key] = read_positive(section.required(key));
  const bool bar = shape.kind == "pipe" || shape.kind == "tbar";
  if (context.dimension == 3) {
    if (bar) read_positive(section.required("length"));
    if (shape.kind == "plate") read_positive(section.required("breadth"));
    return;
  }
  for (const char* key : {"length", "breadth"})
    if (auto v = section.find(key); v && (bar || std::string(key) == "breadth"))
      v->fail(fmt::format("a 2D {} has no {} (it is the section of a long or revolved body)",
                          shape.kind, key));
}

spec::StructureShape read_shape(const yaml::Node& node, const Context& context) {
  if (!node.is_map())
    node.fail("expected a shape such as {type: pipe, diameter: 0.8, position: [0, 1]}");
  std::vector<std::string> kinds;
  for (const auto& [kind, keys] : shape_keys()) kinds.push_back(kind);
  const yaml::Map section =
      node.map({"type", "position", "cell_size", "cell", "diameter", "thickness", "length",
                "tip_angle", "shoulder", "top_angle", "shaft_diameter", "shaft_length", "width",
                "tip", "breadth", "apex_angle", "height"});
  spec::StructureShape shape;
  shape.source = node.where();
  shape.kind = section.required("type").choice(kinds);
  read_dimensions(node, section, context, shape);
  const bool axisymmetric = context.kinematics == Kinematics::Axisymmetric;
  if (axisymmetric && shape.kind == "tbar")
    section.required("type").fail(
        "a T-bar is no body of revolution: use it in plane strain or 3D (in axisymmetry a pipe "
        "is a sphere)");
  const yaml::Node position = section.required("position");
  shape.position = position.vector(context.dimension);
  if (axisymmetric && shape.position.x() != 0)
    position.fail(fmt::format(
        "in an axisymmetric model a structure is a body of revolution about the axis (x = 0): "
        "its position's x must be 0, found {}",
        shape.position.x()));
  if (auto size = section.find("cell_size")) shape.cell_size = read_positive(*size);
  if (auto cell = section.find("cell")) {
    const std::string name =
        cell->choice(context.dimension == 3 ? std::vector<std::string>{"tet4"}
                                            : std::vector<std::string>{"tri3", "tri6", "quad4"});
    shape.cell = *parse_cell_type(name);
  }
  return shape;
}

std::string read_mesh_file(const yaml::Node& node, const std::string& directory) {
  const std::string given = node.text();
  std::filesystem::path path(given);
  if (path.is_relative()) path = std::filesystem::path(directory) / path;
  path = path.lexically_normal();
  const std::string why = given.empty() ? "not found" : unreadable_file_reason(path);
  if (!why.empty())
    node.fail(fmt::format(
        "the structure's mesh file '{}' {} (looked for {}; a relative path starts at the "
        "model file's directory)",
        given, why, path.string()));
  return path.string();
}

// `deformable: {material: steel}`: the structure is a finite-element body of that material
// (docs/theory.md §17.7).
std::string read_deformable(const yaml::Node& node, const Context& context) {
  if (!node.is_map())
    node.fail("expected the structure's material, e.g. deformable: {material: steel}; found " +
              node.describe());
  const yaml::Map section = node.map({"material"});
  return read_reference(section.required("material"), "material", context.materials);
}

spec::Structure read_structure(const yaml::Node& node, const std::string& directory,
                               const Context& context) {
  const yaml::Map section = node.map({"name", "shape", "mesh", "rigid", "deformable", "density",
                                      "mass", "weight", "reference_point", "contact"});
  spec::Structure s;
  s.source = node.where();
  const yaml::Node name = section.required("name");
  s.name = name.text();
  if (s.name.empty() || s.name.find_first_of(" ,\"/\\:") != std::string::npos)
    name.fail(fmt::format(
        "expected a name without spaces, commas, quotes, slashes or colons (it names files and "
        "history columns), found '{}'",
        s.name));
  if (auto contact = section.find("contact")) s.contact = read_contact(*contact, context);
  if (section.exactly_one_of({"shape", "mesh"}) == "shape")
    s.shape = read_shape(section.required("shape"), context);
  else
    s.mesh_file = read_mesh_file(section.required("mesh"), directory);
  if (auto deformable = section.find("deformable")) {
    s.rigid = false;
    s.material = read_deformable(*deformable, context);
  }
  if (auto rigid = section.find("rigid")) {
    if (rigid->boolean() != s.rigid)
      rigid->fail(s.rigid ? "a deformable structure is made by its material: give deformable: "
                            "{material: <a materials entry>} instead of rigid: false"
                          : "a structure is either rigid or deformable: remove rigid: true");
  }
  // A rigid structure's mass is given; a deformable one's is its material's unless given.
  std::string mass;
  if (s.rigid || section.has("density") || section.has("mass") || section.has("weight"))
    mass = section.exactly_one_of({"density", "mass", "weight"});
  if (!mass.empty()) {
    const double value = read_positive(section.required(mass));
    (mass == "density" ? s.density : mass == "mass" ? s.mass : s.weight) = value;
  }
  if (auto reference = section.find("reference_point"); reference && !s.rigid)
    reference->fail(
        "a deformable structure has no rigid-body motion to refer to a point: remove "
        "reference_point");
  if (auto reference = section.find("reference_point")) {
    s.reference_point = reference->vector(context.dimension);
    if (context.kinematics == Kinematics::Axisymmetric && s.reference_point->x() != 0)
      reference->fail(
          fmt::format("in an axisymmetric model the reference point is on the axis: its x must "
                      "be 0, found {}",
                      s.reference_point->x()));
  }
  return s;
}

// The rotational part of a drive: one expression about z in 2D (~ for free), a list of three in
// 3D; into components 3..5. None in axisymmetry.
void read_rotation(const yaml::Node& node, const Context& context, bool free_allowed,
                   std::array<std::string, 6>& into) {
  if (context.kinematics == Kinematics::Axisymmetric)
    node.fail(
        "in an axisymmetric model a structure is a body of revolution: it cannot turn (only its "
        "axial motion is free); remove this key");
  if (context.dimension == 3) {
    const auto v = read_expression_vector(node, 3, time_only, free_allowed, "");
    std::copy(v.begin(), v.end(), into.begin() + 3);
  } else if (!node.is_null() || !free_allowed) {
    into[5] = read_expression(node, time_only);
  }
}

}  // namespace

spec::StructureNodes read_structure_nodes(const yaml::Node& node, const Context& context) {
  spec::StructureNodes nodes;
  nodes.source = node.where();
  using Kind = spec::StructureNodes::Kind;
  if (node.is_map()) {
    const yaml::Map box = node.map({"min", "max"});
    nodes.kind = Kind::Box;
    nodes.min = box.required("min").vector(context.dimension);
    nodes.max = box.required("max").vector(context.dimension);
    for (int i = 0; i < context.dimension; ++i)
      if (nodes.min(i) > nodes.max(i))
        box.required("max").fail(fmt::format("expected max >= min in every component ({} > {})",
                                             nodes.min(i), nodes.max(i)));
    return nodes;
  }
  if (!node.is_scalar())
    node.fail(
        "expected the structure's nodes: all, top, bottom, left, right, a node group of its Gmsh "
        "mesh, or a box {min: [..], max: [..]}; found " +
        node.describe());
  static const std::map<std::string, Kind> kinds = {{"all", Kind::All},
                                                    {"top", Kind::Top},
                                                    {"bottom", Kind::Bottom},
                                                    {"left", Kind::Left},
                                                    {"right", Kind::Right}};
  const std::string text = node.text();
  const auto it = kinds.find(text);
  nodes.kind = it != kinds.end() ? it->second : Kind::Group;
  if (nodes.kind == Kind::Group) nodes.group = text;
  return nodes;
}

namespace {

// How a phase drives a deformable structure on a set of its nodes: a prescribed displacement or
// velocity per component, or a force (the set's total) on the free ones.
spec::StructureDrive read_nodal_drive(const std::string& name, const yaml::Node& node,
                                      const Context& context) {
  if (!node.is_map())
    node.fail(
        "expected a drive of the structure's nodes, e.g. {nodes: top, velocity: [0, -0.1]}; "
        "found " +
        node.describe());
  const yaml::Map section = node.map(
      {"nodes", "displacement", "velocity", "force", "rotation", "angular_velocity", "moment"});
  for (const char* key : {"rotation", "angular_velocity", "moment"})
    if (auto turning = section.find(key))
      turning->fail(fmt::format(
          "'{}' is deformable: it has no rigid-body rotation to prescribe or load; drive the "
          "displacement, velocity or force of its nodes",
          name));
  spec::StructureDrive drive;
  drive.structure = name;
  drive.source = node.where();
  drive.nodes = read_structure_nodes(section.required("nodes"), context);
  if (section.has("displacement") && section.has("velocity"))
    section.required("velocity").fail("give either displacement or velocity, not both");
  drive.velocity = section.has("velocity");
  const int dim = context.dimension;
  for (const char* key : {"displacement", "velocity", "force"})
    if (auto value = section.find(key)) {
      const auto v = read_expression_vector(*value, dim, time_only, true, "");
      std::copy(v.begin(), v.end(),
                std::string(key) == "force" ? drive.load.begin() : drive.motion.begin());
      if (context.kinematics == Kinematics::Axisymmetric && std::string(key) == "force" &&
          !v[0].empty() && v[0] != "0")
        value->items()[0].fail(
            "in an axisymmetric model a radial force on a set of nodes is a ring load that "
            "geompm does not apply: give ~ or 0 for x");
    }
  static const char* names[] = {"x", "y", "z"};
  for (int c = 0; c < dim; ++c)
    if (!drive.motion[c].empty() && !drive.load[c].empty())
      node.fail(fmt::format(
          "the {} component of these nodes of '{}' is both prescribed and loaded; a prescribed "
          "component takes whatever force it needs (its reaction): give ~ for it in the force",
          names[c], name));
  return drive;
}

spec::StructureDrive read_drive(const std::string& name, const yaml::Node& node,
                                const Context& context) {
  const yaml::Map section =
      node.map({"displacement", "velocity", "rotation", "angular_velocity", "force", "moment"});
  spec::StructureDrive drive;
  drive.structure = name;
  drive.source = node.where();
  const int dim = context.dimension;
  const auto translation =
      section.find("displacement") ? section.find("displacement") : section.find("velocity");
  if (section.has("displacement") && section.has("velocity"))
    section.required("velocity").fail("give either displacement or velocity, not both");
  if (section.has("rotation") && section.has("angular_velocity"))
    section.required("angular_velocity").fail("give either rotation or angular_velocity, not both");
  drive.velocity = section.has("velocity") || section.has("angular_velocity");
  if ((section.has("displacement") && section.has("angular_velocity")) ||
      (section.has("velocity") && section.has("rotation")))
    node.fail(
        "prescribe the motion one way: displacement with rotation, or velocity with "
        "angular_velocity");
  if (translation) {
    const auto v = read_expression_vector(*translation, dim, time_only, true, "");
    std::copy(v.begin(), v.end(), drive.motion.begin());
    if (context.kinematics == Kinematics::Axisymmetric && !v[0].empty() && v[0] != "0")
      translation->items()[0].fail(
          "in an axisymmetric model a structure moves only along the axis: its x component "
          "must be ~ or 0");
  }
  if (auto rotation = section.find("rotation"))
    read_rotation(*rotation, context, true, drive.motion);
  if (auto rotation = section.find("angular_velocity"))
    read_rotation(*rotation, context, true, drive.motion);
  if (auto force = section.find("force")) {
    const auto v = read_expression_vector(*force, dim, time_only, true, "");
    std::copy(v.begin(), v.end(), drive.load.begin());
  }
  if (auto moment = section.find("moment")) read_rotation(*moment, context, true, drive.load);
  // A component is either moved or loaded: both would fight.
  static const char* names[] = {
      "x", "y", "z", "rotation about x", "rotation about y", "rotation about z"};
  for (int c = 0; c < 6; ++c)
    if (!drive.motion[c].empty() && !drive.load[c].empty())
      node.fail(fmt::format(
          "the {} component of '{}' is both prescribed and loaded; a prescribed component takes "
          "whatever force it needs (its reaction): give ~ for it in the force or moment",
          names[c], name));
  return drive;
}

}  // namespace

std::vector<spec::Structure> read_structures(const yaml::Node& node, const std::string& directory,
                                             Context& context) {
  if (!node.is_list())
    node.fail(
        "expected a list of structures, e.g. - {name: pipe, shape: {type: pipe, ...}, "
        "weight: 6}; found " +
        node.describe());
  std::vector<spec::Structure> structures;
  for (const yaml::Node& item : node.items()) {
    spec::Structure s = read_structure(item, directory, context);
    for (const spec::Structure& other : structures)
      if (other.name == s.name)
        item.fail(fmt::format("the structure name '{}' is already used by {} (line {})", s.name,
                              other.source.key_path, other.source.line));
    context.structures.push_back(s.name);
    if (!s.rigid) context.deformable_structures.push_back(s.name);
    structures.push_back(std::move(s));
  }
  return structures;
}

std::vector<spec::StructureDrive> read_structure_drives(const yaml::Node& node,
                                                        const Context& context) {
  if (!node.is_map())
    node.fail(
        "expected a map of structures to their drive, e.g. pipe: {velocity: [0.24, ~]}; "
        "found " +
        node.describe());
  std::vector<spec::StructureDrive> drives;
  for (const auto& [name, drive] : node.entries()) {
    if (std::find(context.structures.begin(), context.structures.end(), name) ==
        context.structures.end())
      drive.fail(fmt::format("no structure named '{}'{}; defined: {}", name,
                             yaml::did_you_mean(name, context.structures),
                             context.structures.empty() ? "none (add a top-level structures list)"
                                                        : yaml::join(context.structures)));
    const bool deformable =
        std::find(context.deformable_structures.begin(), context.deformable_structures.end(),
                  name) != context.deformable_structures.end();
    if (!deformable) {
      drives.push_back(read_drive(name, drive, context));
      continue;
    }
    // A deformable structure: one drive of a set of its nodes, or a list of them.
    if (drive.is_list()) {
      for (const yaml::Node& item : drive.items())
        drives.push_back(read_nodal_drive(name, item, context));
    } else {
      drives.push_back(read_nodal_drive(name, drive, context));
    }
  }
  return drives;
}

void read_structure_history(const yaml::Map& section, const Context& context,
                            spec::History& history) {
  const std::vector<std::string> quantities = {
      "reaction",       "moment",   "displacement",  "rotation",      "phase_displacement",
      "phase_rotation", "position", "contact_force", "section_stress"};
  history.quantity = section.required("quantity").choice(quantities);
  history.structure =
      read_reference(section.required("structure"), "structure", context.structures);
  for (const char* key : {"boundary", "point_set", "footing"})
    if (auto other = section.find(key))
      other->fail(fmt::format("a history of a structure takes no {}", key));
  const bool turning = history.quantity == "moment" || history.quantity.ends_with("rotation");
  const bool deformable =
      std::find(context.deformable_structures.begin(), context.deformable_structures.end(),
                history.structure) != context.deformable_structures.end();
  if (deformable && turning && history.quantity != "moment")
    section.required("quantity")
        .fail(fmt::format("'{}' is deformable: it has no rigid-body rotation (give the "
                          "displacement of some of its "
                          "nodes instead)",
                          history.structure));
  const bool of_nodes = history.quantity == "displacement" ||
                        history.quantity == "phase_displacement" || history.quantity == "position";
  if (auto nodes = section.find("nodes")) {
    if (!deformable || !of_nodes)
      nodes->fail(
          "nodes are given for the displacement, phase_displacement or position of a "
          "deformable structure (the mean of those nodes)");
    history.nodes = read_structure_nodes(*nodes, context);
  }
  if (history.quantity == "section_stress") {
    // The mean normal stress over a cross section of a deformable structure (eq. 17.15).
    if (!deformable)
      section.required("quantity")
          .fail("section_stress is the stress in a deformable structure; a rigid one has none");
    const yaml::Map cut = section.required("section").map({"point", "normal"});
    history.section_point = cut.required("point").vector(context.dimension);
    history.section_normal = cut.required("normal").vector(context.dimension);
    if (!(history.section_normal.norm() > 0))
      cut.required("normal").fail("expected a non-zero normal of the section");
    if (auto component = section.find("component"))
      component->fail("section_stress is the normal stress n . sigma n: it takes no component");
    return;
  }
  if (auto cut = section.find("section"))
    cut->fail("a section is given for quantity: section_stress only");
  const yaml::Node component = section.required("component");
  if (turning && context.dimension == 2) {
    // In 2D the one axis of rotation is z.
    if (component.text() != "z" && component.text() != "2")
      component.fail(fmt::format("in a 2D model a {} is about z: expected z, found {}",
                                 history.quantity, component.describe()));
    history.component = 2;
  } else {
    history.component = read_component(component, context.dimension);
  }
}

}  // namespace geompm::model_reader
