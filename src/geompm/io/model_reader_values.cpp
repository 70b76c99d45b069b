// Checks on single values shared by several sections of the model file.
#include <fmt/format.h>
#include <muParser.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "geompm/core/expression.hpp"
#include "geompm/io/model_reader_sections.hpp"

namespace geompm::model_reader {

namespace {

std::vector<std::string> component_names(int dimension) {
  if (dimension == 3) return {"x", "y", "z"};
  return {"x", "y"};
}

// The variables an expression refers to, undefined ones included, so that a load written as a
// function of x is caught here instead of being evaluated silently at x = 0.
std::vector<std::string> used_variables(const std::string& text) {
  mu::Parser parser;
  parser.DefineConst("pi", M_PI);
  parser.DefineConst("e", M_E);
  parser.SetExpr(text);
  std::vector<std::string> names;
  for (const auto& [name, address] : parser.GetUsedVar()) names.push_back(name);
  return names;
}

// The value of an expression without variables.
double constant_value(const std::string& text) {
  mu::Parser parser;
  parser.DefineConst("pi", M_PI);
  parser.DefineConst("e", M_E);
  parser.SetExpr(text);
  return parser.Eval();
}

}  // namespace

const char* component_name(int component) {
  static const char* names[] = {"x", "y", "z"};
  return component >= 0 && component < 3 ? names[component] : "?";
}

int read_component(const yaml::Node& node, int dimension) {
  const std::vector<std::string> names = component_names(dimension);
  if (node.is_scalar()) {
    const std::string text = node.text();
    for (int i = 0; i < dimension; ++i)
      if (text == names[i] || text == std::to_string(i)) return i;
  }
  node.fail(fmt::format("expected a component of the {}D model: {} (or {}), found {}", dimension,
                        yaml::join(names), dimension == 3 ? "0, 1, 2" : "0, 1", node.describe()));
}

std::string read_expression(const yaml::Node& node, const std::vector<std::string>& variables) {
  if (!node.is_scalar())
    node.fail(
        "expected an expression (a number, or a formula in quotes such as \"-0.1*t\"), "
        "found " +
        node.describe());
  const std::string text = node.text();
  if (text.find_first_not_of(" \t") == std::string::npos) node.fail("the expression is empty");
  try {
    Expression compiled(text);
  } catch (const std::invalid_argument& e) {
    node.fail(e.what());
  }
  std::vector<std::string> used;
  try {
    used = used_variables(text);
  } catch (const mu::Parser::exception_type& e) {
    node.fail("invalid expression '" + text + "': " + e.GetMsg());
  }
  for (const std::string& name : used)
    if (std::find(variables.begin(), variables.end(), name) == variables.end())
      node.fail(fmt::format("the expression '{}' uses '{}', but here it may use only {}", text,
                            name, variables.empty() ? "constants" : yaml::join(variables)));
  // A constant ("1/0", "log(0)") has one value: a non-finite one is refused here, at its line.
  if (used.empty()) {
    const double value = constant_value(text);
    if (!std::isfinite(value))
      node.fail(
          fmt::format("the expression '{}' is {}; expected a finite number (a division by "
                      "zero, the log of 0, the root of a negative number?)",
                      text, std::isnan(value) ? "nan" : (value > 0 ? "inf" : "-inf")));
    const double magnitude = std::abs(value);
    if (magnitude > yaml::largest_magnitude || (value != 0 && magnitude < yaml::smallest_magnitude))
      node.fail(
          fmt::format("the expression '{}' is {:g}; expected 0 or a magnitude between {:g} "
                      "and {:g}",
                      text, value, yaml::smallest_magnitude, yaml::largest_magnitude));
  }
  return text;
}

std::array<std::string, 3> read_expression_vector(const yaml::Node& node, int dimension,
                                                  const std::vector<std::string>& variables,
                                                  bool free_allowed, const std::string& unused) {
  const char* layout = dimension == 3 ? "[x, y, z]" : "[x, y]";
  if (!node.is_list())
    node.fail(fmt::format("expected a list of {} components {}, found {}", dimension, layout,
                          node.describe()));
  const std::vector<yaml::Node> items = node.items();
  if (static_cast<int>(items.size()) != dimension)
    node.fail(fmt::format("expected a list of {} components {} (the model is {}D), found {}",
                          dimension, layout, dimension, items.size()));
  std::array<std::string, 3> out = {unused, unused, unused};
  for (int i = 0; i < dimension; ++i) {
    if (items[i].is_null()) {
      if (!free_allowed) items[i].fail("a value is needed for every component (write 0 for none)");
      out[i] = "";
    } else {
      out[i] = read_expression(items[i], variables);
    }
  }
  return out;
}

std::string read_reference(const yaml::Node& node, const std::string& kind,
                           const std::vector<std::string>& defined) {
  const std::string name = node.text();
  if (std::find(defined.begin(), defined.end(), name) == defined.end())
    node.fail(fmt::format("no {} named '{}'{}; defined: {}", kind, name,
                          yaml::did_you_mean(name, defined),
                          defined.empty() ? "none" : yaml::join(defined)));
  return name;
}

std::string read_boundary_name(const yaml::Node& node, const Context& context) {
  const std::string name = node.text();
  if (name.empty()) node.fail("expected a boundary name, found an empty text");
  // An imported mesh's boundaries are its physical groups, known only after import.
  if (context.boundaries.empty()) return name;
  std::vector<std::string> known = context.boundaries;
  known.insert(known.end(), context.node_sets.begin(), context.node_sets.end());
  if (std::find(known.begin(), known.end(), name) == known.end())
    node.fail(fmt::format(
        "no boundary '{}' on the generated mesh{}; its boundaries are: {}{}", name,
        yaml::did_you_mean(name, known), yaml::join(context.boundaries),
        context.node_sets.empty() ? "" : "; the node sets: " + yaml::join(context.node_sets)));
  return name;
}

double read_positive(const yaml::Node& node) {
  const double value = node.number();
  if (!(value > 0)) node.fail(fmt::format("expected a number > 0, found {}", value));
  return value;
}

double read_non_negative(const yaml::Node& node) {
  const double value = node.number();
  if (!(value >= 0)) node.fail(fmt::format("expected a number >= 0, found {}", value));
  return value;
}

double read_fill_fraction(const yaml::Node& node, const std::string& what) {
  const double value = node.number();
  if (!(value > 0.0 && value <= 1.0))
    node.fail(fmt::format("expected a fraction of {}, 0 < fill <= 1, found {}", what, value));
  return value;
}

}  // namespace geompm::model_reader
