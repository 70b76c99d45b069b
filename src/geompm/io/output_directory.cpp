#include "geompm/io/output_directory.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <string>
#include <system_error>

#include "geompm/core/error.hpp"

namespace geompm {

namespace fs = std::filesystem;

namespace {

// The deepest part of `dir` that exists ("." for a relative path none of whose parts exists).
fs::path existing_part(const fs::path& dir) {
  fs::path part = dir;
  std::error_code error;
  while (!part.empty() && !fs::exists(fs::symlink_status(part, error))) part = part.parent_path();
  return part.empty() ? fs::path(".") : part;
}

[[noreturn]] void refuse(const fs::path& dir, const std::string& why) {
  throw InputError(
      fmt::format("{}: cannot use it as the output directory (-o): {}", dir.string(), why));
}

}  // namespace

void prepare_output_directory(const fs::path& dir) {
  std::error_code error;
  const fs::file_status status = fs::status(dir, error);
  if (fs::exists(status) && !fs::is_directory(status))
    refuse(dir, "it is an existing file, not a directory; give another name or remove the file");
  const fs::path existing = existing_part(dir);
  if (!fs::is_directory(existing))
    refuse(dir, fmt::format("'{}' is a file, not a directory", existing.string()));
  fs::create_directories(dir, error);
  if (error)
    refuse(dir,
           fmt::format("cannot create it inside '{}': {}", existing.string(), error.message()));
  // A directory that exists need not be writable (read-only, another user's): try, with a file
  // of a name no run writes, rather than guess from permission bits (root ignores them).
  const fs::path probe = dir / fmt::format(".geompm-write-test-{}", static_cast<long>(::getpid()));
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  if (fd < 0) {
    const int reason = errno;
    refuse(dir, fmt::format("cannot create files in it: {}", std::strerror(reason)));
  }
  ::close(fd);
  fs::remove(probe, error);
}

void remove_stale_temporaries(const fs::path& dir) {
  std::error_code error;
  if (!fs::is_directory(dir, error)) return;
  for (fs::directory_iterator it(dir, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name.size() > 1 && name[0] == '.' && name.find(".tmp-") != std::string::npos &&
        it->is_regular_file(error)) {
      std::error_code ignored;
      fs::remove(it->path(), ignored);
    }
  }
}

}  // namespace geompm
