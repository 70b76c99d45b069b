// The model file's surface loads (phases[].surface_loads, docs/user-guide.md): what a valid entry
// reads as, and each malformed one rejected with the file, line, key path and what was expected.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "geompm/io/model_reader.hpp"
#include "model_reader_support.hpp"

namespace geompm {
namespace {

using namespace geompm::testing;

const std::string kLoadsLine = "      - {point_set: side, force: [\"0\", \"-10*t\"]}\n";

/// kValidModel with `entries` (list items, each a line) as the second phase's surface loads.
std::string with_surface_loads(const std::string& entries) {
  return apply(kValidModel, {{kLoadsLine, kLoadsLine + "    surface_loads:\n" + entries}});
}

TEST(ModelReaderSurfaceLoads, ReadsPressuresAndTractions) {
  const spec::Model model = read_model_from_string(
      with_surface_loads("      - {pressure: \"100*t + 2*x\", direction: following, where: {x: "
                         "[0.2, 0.8]}, bodies: [column]}\n"
                         "      - {traction: [5, \"-t\"]}\n"),
      "model.yaml");
  const auto& loads = model.phases.at(1).surface_loads;
  ASSERT_EQ(loads.size(), 2u);
  EXPECT_TRUE(loads[0].pressure);
  EXPECT_EQ(loads[0].components[0], "100*t + 2*x");
  EXPECT_TRUE(loads[0].following);
  ASSERT_TRUE(loads[0].where[0].has_value());
  EXPECT_EQ((*loads[0].where[0])[0], 0.2);
  EXPECT_EQ((*loads[0].where[0])[1], 0.8);
  EXPECT_FALSE(loads[0].where[1].has_value());
  EXPECT_EQ(loads[0].bodies, std::vector<std::string>{"column"});
  EXPECT_FALSE(loads[1].pressure);
  EXPECT_FALSE(loads[1].following);
  EXPECT_EQ(loads[1].components[0], "5");
  EXPECT_EQ(loads[1].components[1], "-t");
  EXPECT_TRUE(model.phases.at(0).surface_loads.empty());
}

struct Case {
  std::string name;
  std::string entry;    // one list item
  std::string key;      // key path after phases[1].surface_loads[0]
  std::string marker;   // where the expected line starts
  std::string message;  // a piece of the expected message
};
void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

class ModelReaderSurfaceLoadErrors : public ::testing::TestWithParam<Case> {};

TEST_P(ModelReaderSurfaceLoadErrors, NameFileLineKeyAndWhatWasExpected) {
  const Case& c = GetParam();
  const std::string text = with_surface_loads("      - " + c.entry + "\n");
  std::string message;
  try {
    read_model_from_string(text, "model.yaml");
    ADD_FAILURE() << "accepted: " << c.entry;
  } catch (const InputError& e) {
    message = e.what();
  }
  const std::string where =
      fmt::format("model.yaml:{}: phases[1].surface_loads[0]{}: ", line_of(text, c.marker), c.key);
  EXPECT_EQ(message.rfind(where, 0), 0u) << "expected '" << where << "' in\n  " << message;
  EXPECT_NE(message.find(c.message), std::string::npos) << message;
}

INSTANTIATE_TEST_SUITE_P(
    Cases, ModelReaderSurfaceLoadErrors,
    ::testing::Values(
        Case{"neither", "{where: {x: [0, 1]}}", "", "{where",
             "expected one of the keys pressure, traction"},
        Case{"both", "{pressure: 1, traction: [0, 1]}", ".traction", "{pressure",
             "give only one of pressure, traction"},
        Case{"unknown_key", "{pressure: 1, follow: true}", ".follow", "{pressure",
             "allowed keys: pressure, traction, direction, where, bodies"},
        Case{"bad_expression", "{pressure: \"2*(t\"}", ".pressure", "{pressure", "2*(t"},
        Case{"undefined_variable", "{pressure: \"z*t\"}", ".pressure", "{pressure",
             "may use only x, y, t"},
        Case{"traction_size", "{traction: [1, 2, 3]}", ".traction", "{traction", "[x, y]"},
        Case{"following_traction", "{traction: [1, 2], direction: following}", ".direction",
             "{traction", "applies to a pressure"},
        Case{"bad_direction", "{pressure: 1, direction: normal}", ".direction", "{pressure",
             "fixed, following"},
        Case{"range_order", "{pressure: 1, where: {x: [2, 1]}}", ".where.x", "{pressure",
             "low (2) must be less than high (1)"},
        Case{"range_size", "{pressure: 1, where: {y: [2]}}", ".where.y", "{pressure",
             "expected a range [low, high] along y"},
        Case{"z_in_2d", "{pressure: 1, where: {z: [0, 1]}}", ".where.z", "{pressure", "x, y"},
        Case{"unknown_body", "{pressure: 1, bodies: [sand]}", ".bodies[0]", "{pressure",
             "no body named 'sand'"}),
    [](const auto& info) { return info.param.name; });

}  // namespace
}  // namespace geompm
