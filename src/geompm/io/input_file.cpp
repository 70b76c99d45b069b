#include "geompm/io/input_file.hpp"

#include <fcntl.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>

namespace geompm {

std::string unreadable_file_reason(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(file, error);
  if (!fs::exists(status)) return "not found";
  if (fs::is_directory(status)) return "is a directory, not a file";
  if (!fs::is_regular_file(status))
    return "is not a regular file (a device, a pipe or a socket), which cannot be read as one";
  const int fd = ::open(file.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return std::string("cannot be read: ") + std::strerror(errno);
  ::close(fd);
  return "";
}

}  // namespace geompm
