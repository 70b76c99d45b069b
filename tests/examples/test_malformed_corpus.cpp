// End-to-end: a corpus of malformed models generated from the examples — each example truncated
// mid-line, a section key deleted, a number turned into NaN, a huge magnitude, quoted text or a
// list — run through `geompm check`. Every one must be refused as bad input: exit 2 with the
// model file named, never a crash (a signal), never accepted (0), never an internal error (4).
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "cli_support.hpp"

namespace {

namespace fs = std::filesystem;

using namespace geompm::testing;

/// The example model files, relative to examples/ ("column/column.yaml"), sorted.
std::vector<std::string> example_models() {
  std::vector<std::string> found;
  const fs::path root = fs::path(GEOMPM_SOURCE_DIR) / "examples";
  for (const auto& entry : fs::recursive_directory_iterator(root))
    if (entry.path().extension() == ".yaml")
      found.push_back(fs::relative(entry.path(), root).string());
  std::sort(found.begin(), found.end());
  return found;
}

struct Mutant {
  std::string name, text;
};

/// The mutations of one example's text: the structural ones (a cut, a deleted key) in `out`, the
/// changed numbers in `numbers`.
void mutate(const std::string& text, std::vector<Mutant>& out, std::vector<Mutant>& numbers) {
  // Cut mid-line in the materials: the later sections (bodies, phases) are missing.
  const std::size_t materials = text.find("\nmaterials:");
  if (materials != std::string::npos) out.push_back({"truncated", text.substr(0, materials + 16)});
  // A section key deleted: its content dangles under the section before, or the section is gone.
  for (const std::string key : {"materials:", "bodies:", "phases:"}) {
    const std::size_t at = text.find("\n" + key);
    if (at == std::string::npos) continue;
    const std::size_t end = text.find('\n', at + 1);
    out.push_back({"no " + key, text.substr(0, at) + text.substr(end)});
  }
  // The first number of a key made into something that is not a usable number.
  for (const std::string key : {"E", "nu", "density", "duration", "cells"}) {
    const std::regex number("\\b" + key + ": (-?[0-9][0-9.eE+-]*)");
    std::smatch match;
    if (!std::regex_search(text, match, number)) continue;
    for (const std::string value : {".nan", "1e300", "\"7\"", "[]"}) {
      const std::size_t at = match.position(1);
      numbers.push_back(
          {key + ": " + value, text.substr(0, at) + value + text.substr(at + match.length(1))});
    }
  }
}

/// Four mutants of the example number `index`: its cut, one deleted key and two changed numbers,
/// each example another (a process start costs some 0.3 s: the whole corpus, some 700, would
/// take minutes; across the examples every kind of mutation is run).
std::vector<Mutant> sample(const std::string& text, std::size_t index) {
  std::vector<Mutant> structural, numbers, out;
  mutate(text, structural, numbers);
  if (!structural.empty()) out.push_back(structural.front());
  if (structural.size() > 1) out.push_back(structural[1 + index % (structural.size() - 1)]);
  for (std::size_t k : {2 * index, 2 * index + 1 + numbers.size() / 2})
    if (!numbers.empty()) out.push_back(numbers[k % numbers.size()]);
  return out;
}

class MalformedCorpus : public GeompmRunTest<::testing::TestWithParam<std::string>> {};

TEST_P(MalformedCorpus, EveryMutantIsRefusedAsBadInput) {
  const fs::path example = fs::path(GEOMPM_SOURCE_DIR) / "examples" / GetParam();
  std::string text = read_text(example);
  ASSERT_FALSE(text.empty());
  // A mesh file named relative to the example is named absolutely, so that the mutant is refused
  // for its mutation, not for a missing mesh.
  text = std::regex_replace(text, std::regex("\\{file: ([A-Za-z0-9_.]+\\.msh)\\}"),
                            "{file: " + example.parent_path().string() + "/$1}");
  const std::vector<std::string> examples = example_models();
  const std::size_t index =
      std::find(examples.begin(), examples.end(), GetParam()) - examples.begin();
  const std::vector<Mutant> all = sample(text, index);
  EXPECT_EQ(all.size(), 4u) << "too few mutations of " << GetParam();
  for (const Mutant& m : all) {
    SCOPED_TRACE(GetParam() + ", " + m.name);
    write("model.yaml", m.text);
    const auto r = geompm({"check", "model.yaml"});
    ASSERT_TRUE(r.exited) << describe(r);
    EXPECT_EQ(r.exit_code, 2) << describe(r);
    EXPECT_TRUE(Contains(r.err, "model.yaml")) << describe(r);
  }
}

INSTANTIATE_TEST_SUITE_P(Examples, MalformedCorpus, ::testing::ValuesIn(example_models()),
                         [](const ::testing::TestParamInfo<std::string>& info) {
                           std::string name = info.param;
                           for (char& c : name)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return name;
                         });

}  // namespace
