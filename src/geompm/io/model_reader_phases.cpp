// Model file section `phases`: what each stage of the analysis applies (gravity, fixities,
// prescribed motion, loads) and how it is stepped and solved.
#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>

#include "geompm/io/model_reader_sections.hpp"

namespace geompm::model_reader {

namespace {

// Prescribed motions and loads are functions of the phase time only: they act on a point set as
// a whole.
const std::vector<std::string> time_only = {"t"};

spec::TimeStepping read_time_step(const yaml::Node& node) {
  spec::TimeStepping step;
  if (node.is_scalar()) {
    // Short form: a fixed step size that may still be cut back when Newton fails.
    step.initial = read_positive(node);
    step.max = step.initial;
    step.min = 1e-3 * step.initial;
    return step;
  }
  const yaml::Map section =
      node.map({"initial", "min", "max", "growth", "cutback", "target_iterations"});
  const yaml::Node initial = section.required("initial");
  step.initial = read_positive(initial);
  step.max = step.initial;
  if (auto max = section.find("max")) step.max = read_positive(*max);
  step.min = 1e-3 * std::min(step.initial, step.max);
  if (auto min = section.find("min")) {
    step.min = read_positive(*min);
    if (step.min > step.max)
      min->fail(fmt::format("min ({}) must not exceed max ({})", step.min, step.max));
  }
  if (step.initial < step.min || step.initial > step.max)
    initial.fail(fmt::format("initial ({}) must lie between min ({}) and max ({})", step.initial,
                             step.min, step.max));
  if (auto growth = section.find("growth")) {
    step.growth = growth->number();
    if (!(step.growth >= 1))
      growth->fail(fmt::format("expected a factor >= 1 (1 = never grow), found {}", step.growth));
  }
  if (auto cutback = section.find("cutback")) {
    step.cutback = cutback->number();
    if (!(step.cutback > 0 && step.cutback < 1))
      cutback->fail(fmt::format("expected a factor in (0, 1), found {}", step.cutback));
  }
  if (auto target = section.find("target_iterations")) {
    step.target_iterations = target->integer();
    if (step.target_iterations < 1)
      target->fail(fmt::format("expected a whole number >= 1, found {}", step.target_iterations));
  }
  return step;
}

// A phase that needs more steps than any run could take would never end (10^20 steps of a
// nanosecond's work is 3000 years), and a step so small that adding it leaves the time where it
// was would repeat for ever: both are refused with what the numbers imply.
void check_step_count(const yaml::Node& node, double duration, const spec::TimeStepping& step) {
  const double fewest = duration / step.max;
  if (fewest > spec::max_steps_per_phase)
    node.fail(
        fmt::format("the phase's duration {:g} takes at least {:.3g} steps of the largest "
                    "time step {:g}; a phase may take at most {:g}: raise the time step "
                    "(max) or shorten the duration",
                    duration, fewest, step.max, spec::max_steps_per_phase));
  if (step.min < 1e-12 * duration)
    node.fail(
        fmt::format("the smallest time step {:g} is below 1e-12 of the phase's duration "
                    "{:g}: such a step would not advance the time (give a larger min, or "
                    "a larger initial step, of which min is 1e-3 by default)",
                    step.min, duration));
}

// The Bossak scheme (docs/theory.md §4.7) with its second-order beta and gamma.
void set_bossak(spec::Dynamics& dynamics, double alpha_m) {
  dynamics.quasi_static = false;
  dynamics.alpha_m = alpha_m;
  dynamics.beta = 0.25 * (1.0 - alpha_m) * (1.0 - alpha_m);
  dynamics.gamma = 0.5 - alpha_m;
}

void read_newmark_parameters(const yaml::Node& newmark, spec::Dynamics& dynamics) {
  if (newmark.is_null()) return;  // "newmark:" alone: the defaults
  const yaml::Map parameters = newmark.map({"beta", "gamma"});
  if (auto beta = parameters.find("beta")) {
    dynamics.beta = beta->number();
    if (!(dynamics.beta > 0 && dynamics.beta <= 0.5))
      beta->fail(fmt::format("Newmark beta must lie in (0, 0.5], found {}", dynamics.beta));
  }
  if (auto gamma = parameters.find("gamma")) {
    dynamics.gamma = gamma->number();
    if (!(dynamics.gamma >= 0.5 && dynamics.gamma <= 1))
      gamma->fail(fmt::format("Newmark gamma must lie in [0.5, 1], found {}", dynamics.gamma));
  }
}

void read_bossak_parameters(const yaml::Node& bossak, spec::Dynamics& dynamics) {
  set_bossak(dynamics, spec::damped_alpha_m);
  if (bossak.is_null()) return;  // "bossak:" alone: the damped preset's alpha_m
  const yaml::Map parameters = bossak.map({"alpha_m"});
  if (auto alpha = parameters.find("alpha_m")) {
    const double alpha_m = alpha->number();
    // Unconditionally stable and second-order for alpha_m in [-1/3, 0] (Wood et al. 1980).
    if (!(alpha_m >= -1.0 / 3.0 && alpha_m <= 0))
      alpha->fail(fmt::format("Bossak alpha_m must lie in [-1/3, 0], found {}", alpha_m));
    set_bossak(dynamics, alpha_m);
  }
}

spec::Dynamics read_dynamics(const yaml::Node& node) {
  spec::Dynamics dynamics;
  constexpr const char* expected =
      "expected quasi_static, newmark, damped, {newmark: {beta, gamma}} or {bossak: {alpha_m}}";
  if (node.is_scalar()) {
    const std::string choice = node.choice({"quasi_static", "newmark", "damped"});
    dynamics.quasi_static = choice == "quasi_static";
    if (choice == "damped") set_bossak(dynamics, spec::damped_alpha_m);
    return dynamics;
  }
  if (!node.is_map()) node.fail(fmt::format("{}; found {}", expected, node.describe()));
  const yaml::Map section = node.map({"newmark", "bossak"});
  const auto newmark = section.find("newmark");
  const auto bossak = section.find("bossak");
  if (newmark.has_value() == bossak.has_value())
    node.fail(fmt::format("{}: give one of newmark and bossak", expected));
  dynamics.quasi_static = false;
  if (newmark) read_newmark_parameters(*newmark, dynamics);
  if (bossak) read_bossak_parameters(*bossak, dynamics);
  return dynamics;
}

spec::Newton read_newton(const yaml::Node& node) {
  const yaml::Map section =
      node.map({"max_iterations", "residual_tolerance", "displacement_tolerance", "line_search",
                "energy_line_search", "tangent_check", "predictor", "extrapolated_patience"});
  spec::Newton newton;
  if (auto iterations = section.find("max_iterations")) {
    newton.max_iterations = iterations->integer();
    if (newton.max_iterations < 1)
      iterations->fail(
          fmt::format("expected a whole number >= 1, found {}", newton.max_iterations));
  }
  if (auto tolerance = section.find("residual_tolerance"))
    newton.residual_tolerance = read_positive(*tolerance);
  if (auto tolerance = section.find("displacement_tolerance"))
    newton.displacement_tolerance = read_positive(*tolerance);
  if (auto halvings = section.find("line_search")) {
    newton.line_search = halvings->integer();
    if (newton.line_search < 0 || newton.line_search > 20)
      halvings->fail(
          fmt::format("expected a whole number from 0 to 20 (the most halvings of a "
                      "correction), found {}",
                      newton.line_search));
  }
  if (auto search = section.find("energy_line_search")) {
    newton.energy_line_search = search->number();
    if (!(newton.energy_line_search >= 0.0 && newton.energy_line_search < 1.0))
      search->fail(
          fmt::format("expected a tolerance from 0 (off) up to, not including, 1: the largest "
                      "|dx . R| a shortened correction may leave, as a fraction of its start; "
                      "found {}",
                      newton.energy_line_search));
  }
  if (auto check = section.find("tangent_check")) {
    newton.tangent_check = check->number();
    if (!(newton.tangent_check >= 0.0 && newton.tangent_check <= 0.1))
      check->fail(
          fmt::format("expected a finite-difference step from 0 (off) to 0.1, as a "
                      "fraction of each Newton correction, found {}",
                      newton.tangent_check));
  }
  if (auto predictor = section.find("predictor"))
    newton.extrapolate = predictor->choice({"zero", "extrapolated"}) == "extrapolated";
  if (auto patience = section.find("extrapolated_patience")) {
    if (!newton.extrapolate)
      patience->fail(
          "extrapolated_patience applies to the extrapolated start only: add "
          "'predictor: extrapolated' or remove it");
    newton.extrapolated_patience = patience->integer();
    if (newton.extrapolated_patience < 1)
      patience->fail(fmt::format("expected a whole number >= 1 (Newton iterations), found {}",
                                 newton.extrapolated_patience));
  }
  return newton;
}

spec::Gravity read_gravity(const yaml::Node& node, const Context& context) {
  const yaml::Map section = node.map({"acceleration", "ramp"});
  spec::Gravity gravity;
  const yaml::Node acceleration = section.required("acceleration");
  gravity.acceleration = acceleration.vector(context.dimension);
  // A radial body force is not axisymmetric gravity: gravity acts along the axis (y).
  if (context.kinematics == Kinematics::Axisymmetric && gravity.acceleration.x() != 0)
    acceleration.fail(
        fmt::format("in an axisymmetric model x is the radius: gravity must act "
                    "along y, so its x component must be 0, found {}",
                    gravity.acceleration.x()));
  gravity.ramp = section.boolean_or("ramp", false);
  return gravity;
}

// The K0 procedure: K0 per material (or one number for all), the bodies it sets (default all).
// It stands for the weight of level ground, so it needs the phase's full, vertical gravity.
spec::K0Procedure read_k0_procedure(const yaml::Node& node, const yaml::Map& phase,
                                    const std::optional<spec::Gravity>& gravity,
                                    const Context& context, bool first_phase) {
  if (!first_phase)
    node.fail(
        "the K0 procedure sets the stresses the analysis starts from: it is allowed only in the "
        "first phase (phases[0])");
  // "k0_procedure:" alone: every material takes its default K0, every body is set.
  const yaml::Map section = node.is_null() ? yaml::Map(node, {}) : node.map({"K0", "bodies"});
  spec::K0Procedure procedure;
  procedure.source = node.where();

  const int vertical = context.dimension - 1;
  const char* axis = context.dimension == 3 ? "z" : "y";
  if (!gravity)
    node.fail(fmt::format(
        "the K0 procedure needs the phase's gravity for the weight of the soil: add gravity: "
        "{{acceleration: {}}}",
        context.dimension == 3 ? "[0, 0, -9.81]" : "[0, -9.81]"));
  const yaml::Map gravity_map = phase.required("gravity").map({"acceleration", "ramp"});
  if (gravity->ramp)
    gravity_map.required("ramp").fail(
        "the K0 procedure starts from the full weight of the soil, so gravity must be full from "
        "the start of the phase: remove 'ramp' (a ramped gravity phase is the alternative to the "
        "K0 procedure, not a part of it)");
  for (int d = 0; d < context.dimension; ++d)
    if (d == vertical ? !(gravity->acceleration(d) < 0) : gravity->acceleration(d) != 0)
      gravity_map.required("acceleration")
          .fail(fmt::format("the K0 procedure is for level ground: gravity must point straight "
                            "down (-{}), with its other components 0",
                            axis));

  if (auto bodies = section.find_non_empty("bodies")) {
    const std::vector<yaml::Node> items = bodies->items();
    for (const yaml::Node& item : items) {
      const std::string name = read_reference(item, "body", context.bodies);
      if (std::find(procedure.bodies.begin(), procedure.bodies.end(), name) !=
          procedure.bodies.end())
        item.fail(fmt::format("the body '{}' is listed twice", name));
      procedure.bodies.push_back(name);
    }
  }
  const std::vector<std::string>& bodies =
      procedure.bodies.empty() ? context.bodies : procedure.bodies;

  const std::optional<yaml::Node> k0 = section.find("K0");
  if (k0 && k0->is_scalar()) {
    const double value = read_positive(*k0);
    for (const std::string& material : context.materials) procedure.k0[material] = value;
  } else if (k0) {
    if (!k0->is_map())
      k0->fail(
          "expected K0 as a number for every material, or a map of materials to numbers "
          "such as {sand: 0.5, clay: 0.65}; found " +
          k0->describe());
    for (const auto& [material, value] : k0->entries()) {
      if (std::find(context.materials.begin(), context.materials.end(), material) ==
          context.materials.end())
        value.fail(fmt::format("no material named '{}'{}; defined: {}", material,
                               yaml::did_you_mean(material, context.materials),
                               yaml::join(context.materials)));
      procedure.k0[material] = read_positive(value);
    }
  }
  // Every material of the bodies set needs a K0, given or by default.
  for (const std::string& body : bodies)
    for (const std::string& material : context.body_materials.at(body)) {
      const auto& defaults = context.materials_with_default_k0;
      if (procedure.k0.count(material) ||
          std::find(defaults.begin(), defaults.end(), material) != defaults.end())
        continue;
      const std::string what = fmt::format(
          "no K0 for the material '{}' (of body '{}'); only mohr_coulomb has a default "
          "(1 - sin phi): give K0: {{{}: ...}}",
          material, body, material);
      if (k0) k0->fail(what);
      const SourceLocation at = node.where();
      throw InputError(SourceLocation{at.file, at.key_path + ".K0", at.line}, what);
    }
  return procedure;
}

void read_fixed_components(const yaml::Node& node, const Context& context, spec::Fixity& fixity) {
  const std::string expected =
      fmt::format("expected normal, all, a component or a list of components such as {}",
                  context.dimension == 3 ? "[x, z]" : "[x, y]");
  if (node.is_scalar()) {
    const std::string value = node.text();
    if (value == "normal") {
      fixity.normal_only = true;
      return;
    }
    if (value == "all") {
      for (int i = 0; i < context.dimension; ++i) fixity.components[i] = true;
      return;
    }
    if (value == "x" || value == "y" || value == "z" || value == "0" || value == "1" ||
        value == "2") {
      fixity.components[read_component(node, context.dimension)] = true;
      return;
    }
    node.fail(fmt::format("{}; found {}", expected, node.describe()));
  }
  if (!node.is_list()) node.fail(fmt::format("{}; found {}", expected, node.describe()));
  const std::vector<yaml::Node> items = node.items();
  if (items.empty()) node.fail(expected + "; found an empty list");
  for (const yaml::Node& item : items) {
    const int component = read_component(item, context.dimension);
    if (fixity.components[component])
      item.fail(fmt::format("the component {} is listed twice", component_name(component)));
    fixity.components[component] = true;
  }
}

// The nodes a fixity or a grid motion acts on: a boundary (or node set), or a plane.
template <class Target>
void read_node_selection(const yaml::Map& section, const Context& context, Target& target) {
  if (section.exactly_one_of({"boundary", "plane"}) == "boundary") {
    target.boundary = read_boundary_name(section.required("boundary"), context);
  } else {
    const yaml::Map plane = section.required("plane").map({"axis", "value"});
    target.plane_axis = read_component(plane.required("axis"), context.dimension);
    target.plane_value = plane.required("value").number();
  }
}

// The displacement or velocity of a prescribed motion (of points or of nodes): one expression
// of t per component, ~ for a free one, at least one prescribed.
template <class Motion>
void read_motion_components(const yaml::Map& section, const Context& context, Motion& motion) {
  const std::string kind = section.exactly_one_of({"displacement", "velocity"});
  motion.velocity = kind == "velocity";
  const yaml::Node components = section.required(kind);
  motion.components = read_expression_vector(components, context.dimension, time_only, true, "");
  if (std::all_of(motion.components.begin(), motion.components.end(),
                  [](const std::string& c) { return c.empty(); }))
    components.fail("every component is free (~); prescribe at least one, or remove the entry");
}

spec::Fixity read_fixity(const yaml::Node& node, const Context& context) {
  const yaml::Map section = node.map({"boundary", "plane", "fix"});
  spec::Fixity fixity;
  fixity.source = node.where();
  read_node_selection(section, context, fixity);
  read_fixed_components(section.required("fix"), context, fixity);
  return fixity;
}

spec::PrescribedMotion read_motion(const yaml::Node& node, const Context& context) {
  const yaml::Map section = node.map({"point_set", "displacement", "velocity"});
  spec::PrescribedMotion motion;
  motion.source = node.where();
  motion.point_set = read_reference(section.required("point_set"), "point set", context.point_sets);
  read_motion_components(section, context, motion);
  return motion;
}

// The nodes as a fixity names them (a boundary, node set or plane), driven like a point set.
spec::GridMotion read_grid_motion(const yaml::Node& node, const Context& context) {
  const yaml::Map section = node.map({"boundary", "plane", "displacement", "velocity"});
  spec::GridMotion motion;
  motion.source = node.where();
  read_node_selection(section, context, motion);
  read_motion_components(section, context, motion);
  return motion;
}

spec::PointSetLoad read_load(const yaml::Node& node, const Context& context) {
  const yaml::Map section = node.map({"point_set", "force"});
  spec::PointSetLoad load;
  load.source = node.where();
  load.point_set = read_reference(section.required("point_set"), "point set", context.point_sets);
  load.components =
      read_expression_vector(section.required("force"), context.dimension, time_only, false, "0");
  return load;
}

// A point set is either moved or loaded in a phase, once: two conditions on one set would fight.
void check_point_set_used_once(const yaml::Node& node, const std::string& point_set,
                               const std::vector<spec::PrescribedMotion>& motions,
                               const std::vector<spec::PointSetLoad>& loads) {
  for (const auto& motion : motions)
    if (motion.point_set == point_set)
      node.fail(
          fmt::format("the point set '{}' already has a prescribed motion in this phase ({}, "
                      "line {}); a point set is either moved or loaded, once per phase",
                      point_set, motion.source.key_path, motion.source.line));
  for (const auto& load : loads)
    if (load.point_set == point_set)
      node.fail(
          fmt::format("the point set '{}' already has a load in this phase ({}, line {}); "
                      "combine the two into one force",
                      point_set, load.source.key_path, load.source.line));
}

spec::Phase read_phase(const yaml::Node& node, const Context& context,
                       const std::vector<spec::Phase>& earlier) {
  const yaml::Map section =
      node.map({"name", "duration", "time_step", "dynamics", "newton", "gravity", "k0_procedure",
                "fixities", "prescribed_motion", "grid_motion", "rigid_footings", "loads",
                "structures", "surface_loads"});
  spec::Phase phase;
  phase.source = node.where();
  const yaml::Node name = section.required("name");
  phase.name = name.text();
  if (phase.name.empty()) name.fail("a phase needs a name");
  for (const spec::Phase& other : earlier)
    if (other.name == phase.name)
      name.fail(fmt::format("the phase name '{}' is already used by {} (line {})", phase.name,
                            other.source.key_path, other.source.line));
  if (auto duration = section.find("duration")) phase.duration = read_positive(*duration);
  const yaml::Node time_step = section.required("time_step");
  phase.time_step = read_time_step(time_step);
  check_step_count(time_step, phase.duration, phase.time_step);
  if (auto dynamics = section.find("dynamics")) phase.dynamics = read_dynamics(*dynamics);
  if (auto newton = section.find_non_empty("newton")) phase.newton = read_newton(*newton);
  if (auto gravity = section.find("gravity")) phase.gravity = read_gravity(*gravity, context);
  if (auto k0 = section.find("k0_procedure"))
    phase.k0_procedure = read_k0_procedure(*k0, section, phase.gravity, context, earlier.empty());
  if (auto fixities = section.find_non_empty("fixities"))
    for (const yaml::Node& item : fixities->items())
      phase.fixities.push_back(read_fixity(item, context));
  if (auto motions = section.find_non_empty("prescribed_motion"))
    for (const yaml::Node& item : motions->items()) {
      spec::PrescribedMotion motion = read_motion(item, context);
      check_point_set_used_once(item, motion.point_set, phase.motions, phase.loads);
      phase.motions.push_back(std::move(motion));
    }
  if (auto motions = section.find_non_empty("grid_motion"))
    for (const yaml::Node& item : motions->items()) {
      spec::GridMotion motion = read_grid_motion(item, context);
      for (const spec::GridMotion& other : phase.grid_motions)
        if (!motion.boundary.empty() && other.boundary == motion.boundary)
          item.fail(
              fmt::format("the nodes of '{}' are already driven in this phase ({}, line {}); "
                          "give one motion per boundary",
                          motion.boundary, other.source.key_path, other.source.line));
      phase.grid_motions.push_back(std::move(motion));
    }
  if (auto footings = section.find("rigid_footings"))
    footings->fail(
        "rigid footings are structures in contact with the soil: give the footing under "
        "`structures:` (- name: footing, shape: {type: footing, width, height, position}, a "
        "density, contact: {tangential: rough} for a rough base) and drive it in the phase's "
        "`structures:`, e.g. footing: {displacement: [0, \"-0.1*t\"], rotation: 0} "
        "(docs/user-guide.md, structures)");
  if (auto loads = section.find_non_empty("loads"))
    for (const yaml::Node& item : loads->items()) {
      spec::PointSetLoad load = read_load(item, context);
      check_point_set_used_once(item, load.point_set, phase.motions, phase.loads);
      phase.loads.push_back(std::move(load));
    }
  if (auto structures = section.find_non_empty("structures"))
    phase.structure_drives = read_structure_drives(*structures, context);
  if (auto loads = section.find_non_empty("surface_loads"))
    phase.surface_loads = read_surface_loads(*loads, context);
  check_phase_expressions(phase);
  return phase;
}

}  // namespace

std::vector<spec::Phase> read_phases(const yaml::Node& node, Context& context) {
  const std::vector<yaml::Node> items = node.items();
  if (items.empty())
    node.fail("expected at least one phase, e.g. - {name: gravity, time_step: 0.1}");
  std::vector<spec::Phase> phases;
  for (const yaml::Node& item : items) phases.push_back(read_phase(item, context, phases));
  return phases;
}

}  // namespace geompm::model_reader
