// A structure's `contact` entry (docs/user-guide.md, "structures"): the tangential law and the
// bodies the structure touches.
#include <fmt/format.h>

#include <algorithm>

#include "geompm/io/model_reader_sections.hpp"

namespace geompm::model_reader {

spec::Contact read_contact(const yaml::Node& node, const Context& context) {
  spec::Contact c;
  c.source = node.where();
  if (node.is_scalar()) {
    if (node.text() != "none")
      node.fail("expected `none` or a map such as {tangential: rough}, found " + node.describe());
    c.enabled = false;
    return c;
  }
  const yaml::Map section =
      node.map({"tangential", "adhesion", "alpha", "friction", "cap", "bodies"});
  if (auto tangential = section.find("tangential"))
    c.tangential = tangential->choice({"smooth", "rough", "adhesion", "friction"});
  // Each law's parameter is given with it, and only with it.
  const auto parameter = [&](const char* key, const char* law) -> std::optional<yaml::Node> {
    auto value = section.find(key);
    if (value && c.tangential != law)
      value->fail(fmt::format("'{}' belongs to tangential: {}, not to tangential: {}", key, law,
                              c.tangential));
    const bool optional =
        std::string(key) == "cap" || std::string(key) == "adhesion" || std::string(key) == "alpha";
    if (!value && c.tangential == law && !optional)
      section.node().fail(fmt::format("tangential: {} needs '{}'", law, key));
    return value;
  };
  // Adhesion is a stress, or a fraction alpha of the undrained strength of the soil it touches.
  if (auto adhesion = parameter("adhesion", "adhesion")) c.adhesion = read_positive(*adhesion);
  if (auto alpha = parameter("alpha", "adhesion")) {
    c.alpha = read_positive(*alpha);
    if (c.alpha > 1.0)
      alpha->fail(
          fmt::format("expected 0 < alpha <= 1 (the shear the interface carries as a "
                      "fraction of the soil's s_u), found {:g}",
                      c.alpha));
    if (c.adhesion > 0.0) alpha->fail("give either 'adhesion' (a stress) or 'alpha', not both");
  }
  if (c.tangential == "adhesion" && c.adhesion == 0.0 && c.alpha == 0.0)
    section.node().fail(
        "tangential: adhesion needs 'adhesion' (a stress) or 'alpha' (a fraction "
        "of the soil's s_u)");
  if (auto friction = parameter("friction", "friction")) c.friction = read_positive(*friction);
  if (auto cap = parameter("cap", "friction")) c.cap = read_positive(*cap);
  if (auto bodies = section.find("bodies"))
    for (const yaml::Node& body : bodies->items()) {
      const std::string name = body.text();
      if (std::find(context.bodies.begin(), context.bodies.end(), name) == context.bodies.end())
        body.fail(
            fmt::format("no body named '{}' (bodies: {})", name, fmt::join(context.bodies, ", ")));
      c.bodies.push_back(name);
    }
  return c;
}

}  // namespace geompm::model_reader
