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

/// `text` with `key: value` in its `numerics: {...}` line: the key's value replaced if the line
/// names it, else the entry added; a `numerics` line appended if the model has none (the examples
/// carry one only where they show an option, so tests set the options they vary this way).
inline std::string with_numerics(std::string text, const std::string& key,
                                 const std::string& value) {
  const std::string entry = key + ": " + value;
  std::size_t line = text.rfind("\nnumerics: {");
  if (text.rfind("numerics: {", 0) == 0) line = 0;
  if (line == std::string::npos) {
    if (!text.empty() && text.back() != '\n') text += '\n';
    return text + "numerics: {" + entry + "}\n";
  }
  const std::size_t open = text.find('{', line), close = text.find('}', open);
  EXPECT_NE(close, std::string::npos) << "numerics line without its closing brace";
  if (close == std::string::npos) return text;
  // The key as a whole entry: after the brace or after ", ".
  for (const std::string lead : {"{", ", "}) {
    const std::size_t at = text.find(lead + key + ": ", open);
    if (at == std::string::npos || at > close) continue;
    const std::size_t start = at + lead.size();
    const std::size_t comma = text.find(", ", start);
    const std::size_t end = comma < close ? comma : close;
    return text.replace(start, end - start, entry);
  }
  return text.insert(open + 1, close == open + 1 ? entry : entry + ", ");
}

/// `text` (a model whose phases are a block list, "  - name: ...") with `settings` as the Newton
/// settings of its phase `phase` ("newton: {settings}"; the first phase if empty), which must not
/// have any yet.
inline std::string with_newton(std::string text, const std::string& settings,
                               const std::string& phase = "") {
  const std::string lead = "  - name: " + phase;
  std::size_t at = text.find(lead + (phase.empty() ? "" : "\n"));
  EXPECT_NE(at, std::string::npos) << "no phase " << phase;
  if (at == std::string::npos) return text;
  const std::size_t end = text.find('\n', at);
  const std::size_t next = text.find("  - name: ", end);
  EXPECT_EQ(text.substr(end, next - end).find("    newton:"), std::string::npos)
      << "the phase has Newton settings already";
  return text.insert(end + 1, "    newton: {" + settings + "}\n");
}

}  // namespace geompm::testing
