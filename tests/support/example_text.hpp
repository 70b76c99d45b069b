// The text of an example model, and edits of it, for tests that run variants of an example (a
// finer mesh, another Poisson's ratio, no VTK output). An edit that no longer matches the example
// fails the test loudly instead of silently testing the unedited model.
#pragma once

#include <gtest/gtest.h>

#include <fstream>
#include <sstream>
#include <string>

namespace geompm::testing {

/// The model file examples/<relative>, as text (a test failure if it is missing or empty).
inline std::string example_text(const std::string& relative) {
  std::ifstream in(std::string(GEOMPM_SOURCE_DIR) + "/examples/" + relative);
  std::stringstream s;
  s << in.rdbuf();
  EXPECT_FALSE(s.str().empty()) << "no example " << relative;
  return s.str();
}

/// `text` with its one occurrence of `from` replaced by `to` (a test failure if not exactly one).
inline std::string replace_once(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "the example no longer holds: " << from;
  if (at == std::string::npos) return text;
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "more than once: " << from;
  return text.replace(at, from.size(), to);
}

}  // namespace geompm::testing
