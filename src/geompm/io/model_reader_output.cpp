// Model file section `output`: ParaView files, history columns, the plots drawn from them and
// when checkpoints are written.
#include <fmt/format.h>

#include <algorithm>
#include <filesystem>

#include "geompm/io/model_reader_sections.hpp"

namespace geompm::model_reader {

namespace {

// The engine writes these two columns first in every history CSV.
const std::vector<std::string> engine_columns = {"time", "step"};

const std::vector<std::string> vector_quantities = {"reaction", "displacement", "velocity",
                                                    "position", "load"};
const std::vector<std::string> scalar_quantities = {
    "kinetic_energy", "strain_energy",       "newton_iterations",
    "time_step",      "mesh_smallest_angle", "mesh_largest_aspect_ratio"};

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

// A column name ends up in a CSV header and is referred to by plots.
void check_column_name(const yaml::Node& at, bool named_by_user, const std::string& name,
                       const std::vector<spec::History>& earlier) {
  if (name.empty()) at.fail("a history column needs a name");
  if (contains(engine_columns, name))
    at.fail(
        fmt::format("'{}' is a column the history always has (time, step come first); "
                    "choose another name",
                    name));
  if (name.find_first_of(",\"\n\r") != std::string::npos)
    at.fail(
        fmt::format("the column name '{}' may not contain commas, quotes or line breaks", name));
  for (const spec::History& other : earlier)
    if (other.name == name)
      at.fail(fmt::format("the history column '{}' is already defined by {} (line {}){}", name,
                          other.source.key_path, other.source.line,
                          named_by_user ? "" : "; give this one a different name"));
}

// The column's name: given, or quantity[_target][_component].
spec::History named_history(const yaml::Node& node, const yaml::Map& section, spec::History history,
                            const std::vector<spec::History>& earlier) {
  const std::optional<yaml::Node> name = section.find("name");
  if (name) {
    history.name = name->text();
  } else {
    history.name = history.quantity;
    for (const std::string* target : {&history.boundary, &history.point_set, &history.structure})
      if (!target->empty()) history.name += "_" + *target;
    if (history.component >= 0)
      history.name += std::string("_") + component_name(history.component);
  }
  check_column_name(name.value_or(node), name.has_value(), history.name, earlier);
  return history;
}

spec::History read_history(const yaml::Node& node, const Context& context,
                           const std::vector<spec::History>& earlier) {
  const yaml::Map section = node.map({"quantity", "boundary", "point_set", "footing", "structure",
                                      "component", "name", "nodes", "section"});
  spec::History history;
  history.source = node.where();
  if (section.has("structure")) {
    read_structure_history(section, context, history);
    return named_history(node, section, std::move(history), earlier);
  }
  for (const char* key : {"nodes", "section"})
    if (auto value = section.find(key))
      value->fail(
          fmt::format("{} is given for a history of a deformable structure (structure: ...)", key));
  std::vector<std::string> quantities = vector_quantities;
  quantities.insert(quantities.end(), scalar_quantities.begin(), scalar_quantities.end());
  const std::string& quantity = history.quantity = section.required("quantity").choice(quantities);

  if (auto footing = section.find("footing"))
    footing->fail(
        "rigid footings are structures now: measure the footing with structure: <name> "
        "(quantity displacement, or contact_force for the force the soil exerts on it)");
  if (contains(vector_quantities, quantity)) {
    // A boundary (or node set) has a reaction, and the displacement its grid motion prescribes.
    const bool on_boundary = quantity == "reaction" || quantity == "displacement";
    const std::string target =
        on_boundary ? section.exactly_one_of({"boundary", "point_set"}) : "point_set";
    if (!on_boundary)
      if (auto other = section.find("boundary"))
        other->fail(
            fmt::format("{} is measured on a point set: give point_set (a boundary "
                        "is only for reaction and displacement)",
                        quantity));
    if (target == "boundary")
      history.boundary = read_boundary_name(section.required("boundary"), context);
    else
      history.point_set =
          read_reference(section.required("point_set"), "point set", context.point_sets);
    history.component = read_component(section.required("component"), context.dimension);
  } else {
    for (const char* key : {"boundary", "point_set", "component"})
      if (auto value = section.find(key))
        value->fail(
            fmt::format("{} is one number for the whole model: it takes no {}", quantity, key));
  }

  return named_history(node, section, std::move(history), earlier);
}

std::string read_column(const yaml::Node& node, const std::vector<std::string>& columns) {
  const std::string name = node.text();
  if (!contains(columns, name))
    node.fail(fmt::format("no history column '{}'{}; the columns are: {}", name,
                          yaml::did_you_mean(name, columns), yaml::join(columns)));
  return name;
}

double read_scale(const yaml::Node& node) {
  const double scale = node.number();
  if (scale == 0) node.fail("a scale of 0 would flatten the curve; use 1, or -1 to flip it");
  return scale;
}

// {y: 5.14, label: ...} (a line) or {y: [5.14, 5.40], label: ...} (a band).
spec::PlotReference read_plot_reference(const yaml::Node& node) {
  const yaml::Map section = node.map({"y", "label"});
  spec::PlotReference reference;
  const yaml::Node y = section.required("y");
  if (y.is_list()) {
    const std::vector<yaml::Node> ends = y.items();
    if (ends.size() != 2) y.fail("a reference band is two numbers, [lower, upper]");
    reference.lo = ends[0].number();
    reference.hi = ends[1].number();
    if (!(reference.lo < reference.hi))
      y.fail(fmt::format("a reference band's lower value ({}) must be below its upper ({})",
                         reference.lo, reference.hi));
  } else {
    reference.lo = reference.hi = y.number();
  }
  reference.label = section.text_or("label", "");
  return reference;
}

spec::Plot read_plot(const yaml::Node& node, const std::vector<std::string>& columns,
                     const std::vector<spec::Plot>& earlier) {
  const yaml::Map section = node.map(
      {"file", "x", "y", "x_scale", "y_scale", "title", "x_label", "y_label", "reference"});
  spec::Plot plot;
  plot.source = node.where();
  const yaml::Node file = section.required("file");
  plot.file = file.text();
  if (plot.file.size() <= 4 || !plot.file.ends_with(".png"))
    file.fail(fmt::format("a plot is a PNG image: its file name must end in .png, found '{}'",
                          plot.file));
  if (std::filesystem::path(plot.file).is_absolute())
    file.fail("the plot file is written in the output directory: give a relative name");
  for (const spec::Plot& other : earlier)
    if (other.file == plot.file)
      file.fail(fmt::format("the plot file '{}' is already written by {} (line {})", plot.file,
                            other.source.key_path, other.source.line));

  plot.x = "time";
  if (auto x = section.find("x")) plot.x = read_column(*x, columns);
  const yaml::Node y = section.required("y");
  if (y.is_scalar()) {
    plot.y.push_back(read_column(y, columns));
  } else {
    const std::vector<yaml::Node> items = y.items();
    if (items.empty()) y.fail("expected at least one column to plot");
    for (const yaml::Node& item : items) plot.y.push_back(read_column(item, columns));
  }
  if (auto scale = section.find("x_scale")) plot.x_scale = read_scale(*scale);
  if (auto scale = section.find("y_scale")) plot.y_scale = read_scale(*scale);
  plot.title = section.text_or("title", "");
  plot.x_label = section.text_or("x_label", "");
  plot.y_label = section.text_or("y_label", "");
  if (auto reference = section.find_non_empty("reference")) {
    if (reference->is_list())
      for (const yaml::Node& item : reference->items())
        plot.references.push_back(read_plot_reference(item));
    else
      plot.references.push_back(read_plot_reference(*reference));
  }
  return plot;
}

spec::Checkpoint read_checkpoint_schedule(const yaml::Node& node) {
  const yaml::Map section = node.map({"every_steps", "every_minutes"});
  spec::Checkpoint checkpoint;
  if (auto every = section.find("every_steps")) {
    checkpoint.every_steps = every->integer();
    if (checkpoint.every_steps < 0)
      every->fail(fmt::format("expected a whole number of steps >= 0 (0 = not by steps), found {}",
                              checkpoint.every_steps));
  }
  if (auto every = section.find("every_minutes")) {
    checkpoint.every_minutes = every->number();
    if (checkpoint.every_minutes < 0)
      every->fail(fmt::format("expected a number of minutes >= 0 (0 = not by time), found {}",
                              checkpoint.every_minutes));
  }
  return checkpoint;
}

}  // namespace

spec::Output read_output(const yaml::Node& node, const Context& context) {
  const yaml::Map section = node.map({"vtk", "history", "plots", "checkpoint"});
  spec::Output output;
  if (auto vtk_node = section.find_non_empty("vtk")) {
    const yaml::Map vtk = vtk_node->map({"every", "grid"});
    if (auto every = vtk.find("every")) {
      output.vtk_every = every->integer();
      if (output.vtk_every < 0)
        every->fail(
            fmt::format("expected a whole number >= 0 (0 = never), found {}", output.vtk_every));
    }
    output.vtk_grid = vtk.boolean_or("grid", output.vtk_grid);
  }
  if (auto checkpoint = section.find_non_empty("checkpoint"))
    output.checkpoint = read_checkpoint_schedule(*checkpoint);
  std::vector<std::string> columns = engine_columns;
  if (auto histories = section.find_non_empty("history")) {
    // Each column is summed over its points or nodes every step, and a row of the CSV per step
    // holds them all: a few thousand is already far more than a plot can show.
    if (histories->items().size() > spec::max_history_columns)
      histories->fail(fmt::format("{} history columns; at most {} may be recorded",
                                  histories->items().size(), spec::max_history_columns));
    for (const yaml::Node& item : histories->items()) {
      spec::History history = read_history(item, context, output.histories);
      columns.push_back(history.name);
      output.histories.push_back(std::move(history));
    }
  }
  if (auto plots = section.find_non_empty("plots"))
    for (const yaml::Node& item : plots->items())
      output.plots.push_back(read_plot(item, columns, output.plots));
  return output;
}

}  // namespace geompm::model_reader
