// Where an example's committed reference history lives: the example tier compares each run with
// it, and the verification tests of the long examples check what it says against the literature.
#pragma once

#include <filesystem>
#include <string>

namespace geompm::testing {

/// tests/reference_histories/<directory>__<model>.csv for examples/<directory>/<model>.yaml.
inline std::filesystem::path reference_history_path(const std::string& example) {
  std::string name = example.substr(0, example.size() - std::string(".yaml").size());
  const std::size_t slash = name.find('/');
  if (slash != std::string::npos) name.replace(slash, 1, "__");
  return std::filesystem::path(GEOMPM_SOURCE_DIR) / "tests" / "reference_histories" /
         (name + ".csv");
}

}  // namespace geompm::testing
