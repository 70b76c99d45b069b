// Why a file named in the input cannot be read, said as it is: missing, a directory, a device
// (/dev/zero would be read for ever), unreadable; "not found" for all of them sent users looking
// for a file that was there.
#pragma once

#include <filesystem>
#include <string>

namespace geompm {

/// Empty if `file` is a regular file that can be opened for reading; otherwise the reason,
/// starting with a verb ("not found", "is a directory, not a file", ...).
std::string unreadable_file_reason(const std::filesystem::path& file);

}  // namespace geompm
