// A body's initial stress given directly (bodies.<name>.initial_stress, docs/user-guide.md): read
// as expressions of position per component, and malformed ones rejected with the file, line, key
// path and what was expected.
#include <fmt/format.h>
#include <gtest/gtest.h>

#include "geompm/io/model_reader.hpp"
#include "model_reader_support.hpp"

namespace geompm {
namespace {

using namespace geompm::testing;

const std::string kVelocity = "    initial_velocity: [\"0.1*sin(pi*y/50)\", \"0\"]\n";

std::string with_initial_stress(const std::string& value) {
  return apply(kValidModel, {{kVelocity, kVelocity + "    initial_stress: " + value + "\n"}});
}

TEST(ModelReaderInitialStress, ReadsComponentsAsExpressions) {
  const spec::Model model = read_model_from_string(
      with_initial_stress("{sxx: -66, syy: \"-10*(50 - y)\", sxy: \"0.1*x\"}"), "model.yaml");
  const auto& stress = model.bodies.at(0).initial_stress;
  ASSERT_TRUE(stress.has_value());
  EXPECT_EQ(stress->components[0], "-66");
  EXPECT_EQ(stress->components[1], "-10*(50 - y)");
  EXPECT_EQ(stress->components[2], "0");  // absent: 0
  EXPECT_EQ(stress->components[3], "0.1*x");
  EXPECT_FALSE(read_model_from_string(kValidModel, "model.yaml").bodies.at(0).initial_stress);
}

std::string error_of(const std::string& text) {
  try {
    read_model_from_string(text, "model.yaml");
  } catch (const InputError& e) {
    return e.what();
  }
  ADD_FAILURE() << "accepted";
  return "";
}

TEST(ModelReaderInitialStress, RejectsWhatItCannotRead) {
  struct Case {
    std::string value, key, message;
  };
  for (const Case& c : {
           Case{"{syz: 1}", ".syz", "allowed keys: sxx, syy, szz, sxy"},
           Case{"{sxx: \"-t\"}", ".sxx", "may use only x, y"},
           Case{"{}", "", "expected the Cauchy stress components"},
           Case{"-66", "", "expected a map"},
       }) {
    const std::string text = with_initial_stress(c.value);
    const std::string where = fmt::format(
        "model.yaml:{}: bodies.column.initial_stress{}: ", line_of(text, "initial_stress:"), c.key);
    const std::string message = error_of(text);
    EXPECT_EQ(message.rfind(where, 0), 0u) << "expected '" << where << "' in\n  " << message;
    EXPECT_NE(message.find(c.message), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace geompm
