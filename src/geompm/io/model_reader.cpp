// The model file, top level: the sections in order, and the small ones (analysis, mesh,
// materials, numerics). Bodies and point sets, phases and output have files of their own
// (model_reader_*.cpp); the key layout is documented in docs/user-guide.md.
#include "geompm/io/model_reader.hpp"

#include <fmt/format.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "geompm/io/input_file.hpp"
#include "geompm/io/model_reader_sections.hpp"
#include "geompm/materials/material.hpp"
#include "geompm/solver/linear_solver.hpp"

namespace geompm {

namespace model_reader {

namespace {

Kinematics read_analysis(const yaml::Node& node) {
  const yaml::Map analysis = node.map({"kinematics"});
  const std::string name =
      analysis.required("kinematics").choice({"plane_strain", "axisymmetric", "3d"});
  if (name == "axisymmetric") return Kinematics::Axisymmetric;
  if (name == "3d") return Kinematics::ThreeD;
  return Kinematics::PlaneStrain;
}

std::vector<AxisSegment> read_axis(const yaml::Node& node) {
  if (!node.is_map() && !node.is_list())
    node.fail("expected a segment {length, cells, ratio} or a list of segments, found " +
              node.describe());
  const std::vector<yaml::Node> segments = node.is_list() ? node.items() : std::vector{node};
  if (segments.empty()) node.fail("expected at least one segment {length, cells, ratio}");
  std::vector<AxisSegment> axis;
  for (const yaml::Node& segment_node : segments) {
    const yaml::Map segment = segment_node.map({"length", "cells", "ratio"});
    AxisSegment s;
    s.length = read_positive(segment.required("length"));
    const yaml::Node cells = segment.required("cells");
    s.cells = cells.integer();
    if (s.cells < 1) cells.fail(fmt::format("expected at least 1 cell, found {}", s.cells));
    if (auto ratio = segment.find("ratio")) s.ratio = read_positive(*ratio);
    axis.push_back(s);
  }
  return axis;
}

StructuredMeshSpec read_generated_mesh(const yaml::Node& node, Context& context) {
  const yaml::Map generate = node.map({"cell", "diagonals", "origin", "x", "y", "z"});
  const int dim = context.dimension;
  StructuredMeshSpec mesh;
  mesh.cell_type = dim == 3 ? CellType::Hex8 : CellType::Quad4;
  if (auto cell = generate.find("cell")) {
    const std::string name = cell->choice({"tri3", "tri6", "quad4", "tet4", "hex8"});
    mesh.cell_type = *parse_cell_type(name);
    if (cell_dimension(mesh.cell_type) != dim)
      cell->fail(fmt::format("'{}' cells are {}D but the kinematics '{}' is {}D; use {}", name,
                             cell_dimension(mesh.cell_type), to_string(context.kinematics), dim,
                             dim == 3 ? "tet4 or hex8" : "tri3, tri6 or quad4"));
  }
  if (auto diagonals = generate.find("diagonals")) {
    if (diagonals->choice({"alternating", "crossed"}) == "crossed") {
      if (mesh.cell_type != CellType::Tri3)
        diagonals->fail(fmt::format(
            "crossed diagonals split each rectangle into four tri3 cells, but the cell is '{}'; "
            "set 'cell: tri3' or remove 'diagonals'",
            to_string(mesh.cell_type)));
      mesh.diagonals = Diagonals::Crossed;
    }
  }
  if (auto origin = generate.find("origin")) {
    mesh.origin = origin->vector(dim);
    if (context.kinematics == Kinematics::Axisymmetric && mesh.origin.x() < 0)
      origin->fail(
          fmt::format("in an axisymmetric model x is the radius: the origin's x must be "
                      ">= 0, found {}",
                      mesh.origin.x()));
  }
  const char* axis_names[] = {"x", "y", "z"};
  for (int i = 0; i < dim; ++i) mesh.axes[i] = read_axis(generate.required(axis_names[i]));
  if (dim == 2)
    if (auto z = generate.find("z")) z->fail("a 2D model has no z axis; remove 'z'");

  context.cell_type = mesh.cell_type;
  context.boundaries =
      dim == 3 ? std::vector<std::string>{"left", "right", "front", "back", "bottom", "top"}
               : std::vector<std::string>{"left", "right", "bottom", "top"};
  return mesh;
}

}  // namespace

spec::Mesh read_mesh(const yaml::Node& node, const std::string& model_directory, Context& context) {
  const yaml::Map section = node.map({"generate", "file"});
  spec::Mesh mesh;
  mesh.source = node.where();
  if (section.exactly_one_of({"generate", "file"}) == "generate") {
    mesh.generate = read_generated_mesh(section.required("generate"), context);
    return mesh;
  }
  const yaml::Node file = section.required("file");
  const std::string given = file.text();
  if (given.empty()) file.fail("expected the path of a Gmsh .msh file, found an empty text");
  std::filesystem::path path(given);
  if (path.is_relative()) path = std::filesystem::path(model_directory) / path;
  path = path.lexically_normal();
  if (const std::string why = unreadable_file_reason(path); !why.empty())
    file.fail(
        fmt::format("mesh file '{}' {} (looked for {}; a relative path starts at the "
                    "model file's directory)",
                    given, why, path.string()));
  mesh.file = path.string();
  return mesh;
}

spec::Formulation read_formulation(const yaml::Node& node) {
  const std::string choice = node.choice({"displacement", "f_bar", "mixed"});
  if (choice == "mixed") return spec::Formulation::Mixed;
  return choice == "f_bar" ? spec::Formulation::FBar : spec::Formulation::Displacement;
}

std::vector<spec::Material> read_materials(const yaml::Node& node, Context& context) {
  std::vector<spec::Material> materials;
  for (const auto& [name, material_node] : node.entries()) {
    spec::Material material;
    material.name = name;
    material.source = material_node.where();
    if (name.empty()) material_node.fail("a material needs a name");
    // Every key but "model" and "formulation" is a parameter; which ones the model takes, and
    // their ranges, are the material's own business (create_material), so the reader asks it.
    const std::vector<std::pair<std::string, yaml::Node>> entries = material_node.entries();
    for (const auto& [key, value] : entries) {
      if (key == "model")
        material.model = value.text();
      else if (key == "formulation")
        material.formulation = read_formulation(value);
      else if (key == "surface_tangent")  // a word in the file, a number for the material
        material.parameters[key] = value.choice({"elastic", "plastic"}) == "plastic" ? 1.0 : 0.0;
      else
        material.parameters[key] = value.number();
    }
    const auto entry_of = [&](const std::string& key) -> const yaml::Node* {
      for (const auto& [k, value] : entries)
        if (k == key) return &value;
      return nullptr;
    };
    if (!entry_of("model"))
      throw InputError(SourceLocation{material.source.file, material.source.key_path + ".model",
                                      material.source.line},
                       fmt::format("missing required key 'model' in {}; known models: {}",
                                   material.source.key_path, yaml::join(material_models())));
    try {
      if (create_material(material.model, material.parameters)->default_k0())
        context.materials_with_default_k0.push_back(name);
    } catch (const ParameterError& e) {
      if (const yaml::Node* value = entry_of(e.key())) value->fail(e.what());
      throw InputError(
          SourceLocation{material.source.file, material.source.key_path + "." + e.key(),
                         material.source.line},
          e.what());
    }
    context.materials.push_back(name);
    materials.push_back(std::move(material));
  }
  if (materials.empty())
    node.fail(
        "expected at least one material, e.g. soil: {model: linear_elastic, E: 1000, "
        "nu: 0.3}");
  return materials;
}

// numerics.linear_solver and what the PETSc solvers read besides (docs/user-guide.md, "Linear
// solvers").
void read_linear_solver(const yaml::Map& section, spec::Numerics& numerics) {
  if (auto solver = section.find("linear_solver"))
    numerics.linear_solver = solver->choice(linear_solver_names());
  if (auto options = section.find("petsc_options")) {
    numerics.petsc_options = options->text();
    if (const std::string error = petsc_options_error(numerics.petsc_options); !error.empty())
      options->fail(error);
    if (!uses_petsc(numerics.linear_solver))
      options->fail(
          fmt::format("has no effect with linear_solver: {} (expected a PETSc solver: "
                      "auto, petsc_gamg, petsc_hypre or petsc_mumps)",
                      numerics.linear_solver));
  }
  if (auto limit = section.find("direct_limit")) {
    numerics.direct_limit = limit->integer();
    if (numerics.direct_limit < 0)
      limit->fail(
          fmt::format("expected a number of unknowns >= 0, found {}", numerics.direct_limit));
    if (numerics.linear_solver != "auto")
      limit->fail(
          "has no effect without linear_solver: auto (the size below which it picks the "
          "direct solver)");
  }
}

spec::Numerics read_numerics(const yaml::Node& node) {
  const yaml::Map section = node.map(
      {"interpolation", "formulation", "empty_cell_stiffness", "buffer_layers", "lost_points",
       "linear_solver", "mixed_volume", "mixed_material_pressure", "mixed_pressure_equation",
       "pressure_stabilisation_floor", "mixed_pressure_start", "sparse_node_stiffness",
       "sparse_node_fill", "ghost_penalty", "ghost_penalty_fill", "petsc_options", "direct_limit"});
  spec::Numerics numerics;
  if (auto formulation = section.find("formulation"))
    numerics.formulation = read_formulation(*formulation);
  if (auto interpolation = section.find("interpolation")) {
    const std::string choice = interpolation->choice({"standard", "ddmp", "gimp"});
    numerics.interpolation = choice == "ddmp"   ? spec::Interpolation::DualDomain
                             : choice == "gimp" ? spec::Interpolation::Gimp
                                                : spec::Interpolation::Standard;
    numerics.interpolation_source = interpolation->where();
  }
  if (auto stiffness = section.find("empty_cell_stiffness"))
    numerics.empty_cell_stiffness = read_non_negative(*stiffness);
  if (auto stiffness = section.find("sparse_node_stiffness"))
    numerics.sparse_node_stiffness = read_non_negative(*stiffness);
  if (auto gamma = section.find("ghost_penalty"))
    numerics.ghost_penalty = read_non_negative(*gamma);
  // A fill limit alone would be read and silently do nothing: ask for the stiffness it limits
  // (an explicit 0 is a deliberate switch-off and keeps the limit).
  const auto read_fill_limit = [&section](const char* key, const char* stiffness, const char* what,
                                          const char* equation, double& limit) {
    if (auto fill = section.find(key)) {
      limit = read_fill_fraction(*fill, what);
      if (!section.find(stiffness))
        fill->fail(fmt::format(
            "has no effect without numerics.{0}, the stiffness it limits (e.g. {0}: 1.0e-2; "
            "docs/theory.md eq. {1})",
            stiffness, equation));
    }
  };
  read_fill_limit("sparse_node_fill", "sparse_node_stiffness", "a node's support", "6.2",
                  numerics.sparse_node_fill);
  read_fill_limit("ghost_penalty_fill", "ghost_penalty", "an edge cell", "6.3",
                  numerics.ghost_penalty_fill);
  if (auto floor = section.find("pressure_stabilisation_floor"))
    numerics.pressure_stabilisation_floor = read_non_negative(*floor);
  if (auto layers = section.find("buffer_layers")) {
    // Each layer is a ring of cells around the occupied ones; beyond a few the whole mesh is
    // active, and a count in the millions only costs time.
    numerics.buffer_layers = layers->integer();
    if (numerics.buffer_layers < 0 || numerics.buffer_layers > spec::max_buffer_layers)
      layers->fail(fmt::format("expected a whole number from 0 to {}, found {}",
                               spec::max_buffer_layers, numerics.buffer_layers));
  }
  if (auto lost = section.find("lost_points"))
    numerics.lost_points = lost->choice({"stop", "remove"}) == "remove"
                               ? spec::LostPointPolicy::Remove
                               : spec::LostPointPolicy::Stop;
  if (auto volume = section.find("mixed_volume"))
    numerics.mixed_volume_average = volume->choice({"cell_average", "per_point"}) == "cell_average";
  if (auto pressure = section.find("mixed_material_pressure"))
    numerics.mixed_field_pressure = pressure->choice({"own", "field"}) == "field";
  if (auto equation = section.find("mixed_pressure_equation")) {
    numerics.mixed_incremental_pressure =
        equation->choice({"total", "incremental"}) == "incremental";
    numerics.incremental_pressure_source = equation->where();
    // The field's pressure (theory §14) carries its own mismatch over the steps (eq. 14.2).
    if (numerics.mixed_incremental_pressure && numerics.mixed_field_pressure.value_or(false))
      equation->fail(
          "expected 'total' with mixed_material_pressure: field (the field's pressure carries its "
          "volume mismatch over the steps, docs/theory.md §14); 'incremental' applies to "
          "mixed_material_pressure: own");
  }
  if (auto start = section.find("mixed_pressure_start"))
    numerics.fitted_pressure_start = start->choice({"points", "fitted"}) == "fitted";
  read_linear_solver(section, numerics);
  return numerics;
}

}  // namespace model_reader

spec::Model read_model(const std::string& path) {
  const std::string why = unreadable_file_reason(path);
  if (why == "not found")
    throw InputError(SourceLocation{path, "", 0}, "the model file does not exist");
  if (!why.empty())
    throw InputError(SourceLocation{path, "", 0},
                     "the model file " + why + " (expected a YAML or JSON model)");
  std::ifstream in(path, std::ios::binary);
  std::stringstream text;
  text << in.rdbuf();
  if (!in || in.bad()) throw InputError(SourceLocation{path, "", 0}, "cannot read the model file");
  return read_model_from_string(text.str(), path);
}

spec::Model read_model_from_string(const std::string& text, const std::string& file_name) {
  using namespace model_reader;
  const yaml::Node root = yaml::parse(text, file_name);
  const char* sections = "analysis, mesh, materials, bodies, phases";
  if (root.is_null()) root.fail(fmt::format("the model file is empty; expected {}", sections));
  if (!root.is_map())
    root.fail(fmt::format("expected a map of sections ({}), found {}", sections, root.describe()));
  const yaml::Map top =
      root.map({"title", "analysis", "mesh", "regions", "materials", "bodies", "point_sets",
                "node_sets", "structures", "phases", "output", "numerics"});

  spec::Model model;
  model.file = file_name;
  const std::filesystem::path file_path(file_name.empty() ? "." : file_name);
  model.directory = std::filesystem::absolute(file_path).lexically_normal().parent_path().string();
  if (auto title = top.find_non_empty("title")) model.title = title->text();
  model.kinematics = read_analysis(top.required("analysis"));

  Context context;
  context.kinematics = model.kinematics;
  context.dimension = spatial_dimension(model.kinematics);
  model.mesh = read_mesh(top.required("mesh"), model.directory, context);
  if (auto regions = top.find_non_empty("regions")) model.regions = read_regions(*regions, context);
  model.materials = read_materials(top.required("materials"), context);
  model.bodies = read_bodies(top.required("bodies"), context);
  if (auto point_sets = top.find_non_empty("point_sets"))
    model.point_sets = read_point_sets(*point_sets, context);
  if (auto node_sets = top.find_non_empty("node_sets"))
    model.node_sets = read_node_sets(*node_sets, context);
  if (auto structures = top.find_non_empty("structures"))
    model.structures = read_structures(*structures, model.directory, context);
  model.phases = read_phases(top.required("phases"), context);
  if (auto output = top.find_non_empty("output")) model.output = read_output(*output, context);
  if (auto numerics = top.find_non_empty("numerics")) model.numerics = read_numerics(*numerics);
  return model;
}

}  // namespace geompm
