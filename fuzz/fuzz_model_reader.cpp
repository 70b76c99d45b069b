// libFuzzer target: a model file's text as `geompm check` reads it (read, validate, build). Bad
// input must end in an InputError (exit 2 of the command line); anything else - another
// exception, a crash, a sanitizer report, a hang - is a finding. Run by scripts/check_sanitized.sh
// from the examples as seeds; build with -DGEOMPM_FUZZ=ON (clang).
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string>

#include "geompm/analysis/model.hpp"
#include "geompm/analysis/model_size.hpp"
#include "geompm/core/error.hpp"
#include "geompm/io/model_reader.hpp"

namespace {

// A valid model that is merely large takes seconds to build, which the fuzzer would report as a
// hang; the size estimate (itself under test) decides which models are built.
constexpr double kLargestBuiltCells = 2.0e4;
constexpr double kLargestBuiltPoints = 1.0e5;

void check_model_text(const std::string& text) {
  const auto spec = geompm::read_model_from_string(text, "fuzz.yaml");
  const auto size = geompm::estimate_model_size(spec);
  if (size.cells > kLargestBuiltCells || size.points > kLargestBuiltPoints) return;
  // Imported meshes and models that mesh through Gmsh read files beside the model: none here.
  (void)geompm::build_model(spec);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    check_model_text(text);
  } catch (const geompm::InputError&) {
    // Refused as bad input with a message: what is wanted.
  } catch (const std::exception& e) {
    std::fprintf(stderr, "not an input error: %s\n", e.what());
    std::abort();
  }
  return 0;
}
