// libFuzzer target: a Gmsh .msh file as a model's `mesh: {file: ...}` reads it (through the Gmsh
// API, docs/user-guide.md "Meshes"). A malformed file must end in an InputError naming it;
// anything else is a finding. Seeds: the .msh files of examples/ (scripts/check_sanitized.sh).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>

#include "geompm/core/error.hpp"
#include "geompm/mesh/gmsh_import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  // The Gmsh API reads files only: one file per process, rewritten for each input.
  static const std::string path = "/tmp/geompm_fuzz_mesh_" + std::to_string(getpid()) + ".msh";
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  }
  for (const int dimension : {2, 3}) {
    try {
      (void)geompm::read_gmsh_mesh(path, dimension);
    } catch (const geompm::InputError&) {
    } catch (const std::exception& e) {
      std::fprintf(stderr, "not an input error: %s\n", e.what());
      std::abort();
    }
  }
  return 0;
}
