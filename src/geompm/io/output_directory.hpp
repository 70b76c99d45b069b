// The output directory of a run (geompm run -o DIR), made ready before anything is written: a
// name that is a file, a parent that is a file or cannot be written, are bad input (InputError,
// exit 2) with the reason, not an internal error half-way through the first write.
#pragma once

#include <filesystem>

namespace geompm {

/// Creates `dir` (and its parents) if needed and checks that files can be created in it; throws
/// InputError naming the directory, the part of the path at fault and why.
void prepare_output_directory(const std::filesystem::path& dir);

/// Removes the temporary files a killed writer left in `dir` (".NAME.tmp-PID-N", see
/// write_file_atomically): half-written files that no later run would remove otherwise.
void remove_stale_temporaries(const std::filesystem::path& dir);

}  // namespace geompm
