#include "geompm/io/checkpoint_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iterator>

#include "geompm/core/error.hpp"
#include "geompm/core/fnv1a.hpp"

namespace geompm {

namespace {

// Writes all of `bytes` to the open file `fd`.
bool write_all(int fd, const char* bytes, std::size_t size) {
  while (size > 0) {
    const ssize_t written = ::write(fd, bytes, size);
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) return false;
    bytes += written;
    size -= static_cast<std::size_t>(written);
  }
  return true;
}

[[noreturn]] void fail_write(const std::filesystem::path& file, const std::string& what) {
  throw RunError(fmt::format("cannot write the checkpoint {}: {} ({})", file.string(), what,
                             std::strerror(errno)));
}

// The rename is only durable once the directory entry is on disk too.
void sync_directory(const std::filesystem::path& directory) {
  const int fd = ::open(directory.empty() ? "." : directory.c_str(), O_RDONLY | O_DIRECTORY);
  if (fd < 0) return;
  ::fsync(fd);
  ::close(fd);
}

std::string body_of(std::uint64_t model_hash, const CheckpointSections& sections) {
  ByteWriter body;
  body.put(std::string(GEOMPM_VERSION));
  body.put(model_hash);
  body.put(static_cast<std::uint32_t>(sections.size()));
  for (const auto& [name, data] : sections) {
    body.put(name);
    body.put(data);
  }
  return body.take();
}

}  // namespace

std::filesystem::path checkpoint_temporary(const std::filesystem::path& file) {
  return std::filesystem::path(file.string() + ".tmp");
}

void write_checkpoint_file(const std::filesystem::path& file, std::uint64_t model_hash,
                           const CheckpointSections& sections,
                           const CheckpointWriteOptions& options) {
  const std::string body = body_of(model_hash, sections);
  ByteWriter header;
  for (const char c : checkpoint_magic) header.put(c);
  header.put(checkpoint_format_version);
  header.put(static_cast<std::uint64_t>(body.size()));
  header.put(fnv1a_64(body));

  const std::filesystem::path temporary = checkpoint_temporary(file);
  const int fd = ::open(temporary.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail_write(temporary, "cannot create the file");
  if (options.kill_half_way) {
    write_all(fd, header.bytes().data(), header.bytes().size());
    write_all(fd, body.data(), body.size() / 2);
    ::fsync(fd);
    std::raise(SIGKILL);
  }
  // Header and body apart: a large model's state is not copied once more to join them.
  if (!write_all(fd, header.bytes().data(), header.bytes().size()) ||
      !write_all(fd, body.data(), body.size())) {
    ::close(fd);
    fail_write(temporary, "write failed");
  }
  // Flushed to the disk before the rename: after a crash the name checkpoint.bin never points
  // at data that did not reach it.
  if (::fsync(fd) != 0) {
    ::close(fd);
    fail_write(temporary, "fsync failed");
  }
  if (::close(fd) != 0) fail_write(temporary, "close failed");
  if (::rename(temporary.c_str(), file.c_str()) != 0) fail_write(file, "rename failed");
  sync_directory(file.parent_path());
}

ByteReader CheckpointContents::section(const std::string& name) const {
  for (const auto& [section_name, data] : sections)
    if (section_name == name) return ByteReader(data, fmt::format("{}: section '{}'", file, name));
  throw InputError(
      fmt::format("{}: the checkpoint has no section '{}' (damaged, or written by "
                  "another layout of format version {})",
                  file, name, checkpoint_format_version));
}

CheckpointContents read_checkpoint_file(const std::filesystem::path& file,
                                        std::uint64_t model_hash) {
  CheckpointContents contents;
  contents.file = file.string();
  const std::string& name = contents.file;
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open the checkpoint", name));
  const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};

  if (bytes.size() < checkpoint_header_bytes)
    throw InputError(fmt::format("{}: truncated checkpoint ({} bytes; its header alone has {})",
                                 name, bytes.size(), checkpoint_header_bytes));
  if (bytes.compare(0, sizeof(checkpoint_magic), checkpoint_magic, sizeof(checkpoint_magic)) != 0)
    throw InputError(fmt::format("{}: not a geompm checkpoint (it does not start with '{}')", name,
                                 std::string(checkpoint_magic, sizeof(checkpoint_magic))));
  ByteReader header(std::string_view(bytes).substr(sizeof(checkpoint_magic)), name);
  const auto format = header.get<std::uint32_t>();
  if (format != checkpoint_format_version)
    throw InputError(
        fmt::format("{}: checkpoint format version {}; this geompm ({}) reads format version {} "
                    "only: resume with the geompm that wrote it, or run again without --resume",
                    name, format, GEOMPM_VERSION, checkpoint_format_version));
  const auto length = header.get<std::uint64_t>();
  const auto checksum = header.get<std::uint64_t>();
  const std::uint64_t found = bytes.size() - checkpoint_header_bytes;
  if (found < length)
    throw InputError(fmt::format("{}: truncated checkpoint ({} bytes; its header announces {})",
                                 name, bytes.size(), checkpoint_header_bytes + length));
  if (found > length)
    throw InputError(fmt::format("{}: damaged checkpoint ({} bytes more than its header announces)",
                                 name, found - length));
  const std::string_view body = std::string_view(bytes).substr(checkpoint_header_bytes);
  if (fnv1a_64(body) != checksum)
    throw InputError(
        fmt::format("{}: damaged checkpoint: the checksum of its contents ({}) is not "
                    "the one it was written with ({})",
                    name, fnv1a_hex(fnv1a_64(body)), fnv1a_hex(checksum)));

  ByteReader reader(body, name);
  reader.get(contents.geompm_version);
  reader.get(contents.model_hash);
  if (contents.model_hash != model_hash)
    throw InputError(fmt::format(
        "{}: the checkpoint was written for another model (the text of its model file hashed to "
        "{}, this model file's to {}): resume with the model file the run was started with, "
        "unchanged, or run again without --resume",
        name, fnv1a_hex(contents.model_hash), fnv1a_hex(model_hash)));
  const auto count = reader.get<std::uint32_t>();
  for (std::uint32_t k = 0; k < count; ++k) {
    std::pair<std::string, std::string> section;
    reader.get(section.first);
    reader.get(section.second);
    contents.sections.push_back(std::move(section));
  }
  reader.expect_end();
  return contents;
}

}  // namespace geompm
