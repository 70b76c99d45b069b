#include "geompm/io/checkpoint_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstring>
#include <fstream>
#include <iterator>
#include <stdexcept>

#include "geompm/core/error.hpp"
#include "geompm/core/fnv1a.hpp"

namespace geompm {

namespace {

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

// Bytes the writer gathers before it writes them to the file.
constexpr std::size_t write_buffer_bytes = std::size_t{1} << 20;

}  // namespace

std::filesystem::path checkpoint_temporary(const std::filesystem::path& file) {
  return std::filesystem::path(file.string() + ".tmp");
}

CheckpointWriter::CheckpointWriter(std::filesystem::path file, std::uint64_t model_hash,
                                   std::uint32_t sections, CheckpointWriteOptions options)
    : file_(std::move(file)),
      temporary_(checkpoint_temporary(file_)),
      options_(options),
      checksum_(fnv1a_offset_basis),
      sections_left_(sections) {
  fd_ = ::open(temporary_.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd_ < 0) fail_write(temporary_, "cannot create the file");
  // The header's place: it is written once the body's length and checksum are known.
  buffer_.reserve(write_buffer_bytes);
  buffer_.assign(checkpoint_header_bytes, '\0');
  ByteWriter head;
  head.put(std::string(GEOMPM_VERSION));
  head.put(model_hash);
  head.put(sections);
  body(head.bytes());
}

CheckpointWriter::~CheckpointWriter() {
  if (fd_ >= 0) ::close(fd_);
}

void CheckpointWriter::section(const std::string& name, std::string_view bytes) {
  begin_section(name, bytes.size());
  add(bytes);
}

void CheckpointWriter::begin_section(const std::string& name, std::uint64_t length) {
  if (section_left_ != 0 || sections_left_ == 0)
    throw std::logic_error(fmt::format("checkpoint section '{}' begun out of turn", name));
  --sections_left_;
  ByteWriter head;
  head.put(name);
  head.put(length);
  body(head.bytes());
  section_left_ = length;
}

void CheckpointWriter::add(std::string_view bytes) {
  if (bytes.size() > section_left_)
    throw std::logic_error("a checkpoint section given more bytes than it announced");
  section_left_ -= bytes.size();
  body(bytes);
}

void CheckpointWriter::body(std::string_view bytes) {
  checksum_ = fnv1a_64(bytes, checksum_);
  length_ += bytes.size();
  if (buffer_.size() + bytes.size() > write_buffer_bytes) flush();
  if (bytes.size() >= write_buffer_bytes)
    write_at(~std::uint64_t{0}, bytes);
  else
    buffer_.append(bytes);
}

void CheckpointWriter::flush() {
  write_at(~std::uint64_t{0}, buffer_);
  buffer_.clear();
}

// At `offset`, or (~0) where the file is.
void CheckpointWriter::write_at(std::uint64_t offset, std::string_view bytes) {
  const char* data = bytes.data();
  for (std::size_t left = bytes.size(); left > 0;) {
    const ssize_t written =
        offset == ~std::uint64_t{0}
            ? ::write(fd_, data, left)
            : ::pwrite(fd_, data, left, static_cast<off_t>(offset + (data - bytes.data())));
    if (written < 0 && errno == EINTR) continue;
    if (written <= 0) fail_write(temporary_, "write failed");
    data += written;
    left -= static_cast<std::size_t>(written);
  }
}

void CheckpointWriter::commit() {
  if (section_left_ != 0 || sections_left_ != 0)
    throw std::logic_error("a checkpoint committed before its sections were all written");
  flush();
  ByteWriter header;
  for (const char c : checkpoint_magic) header.put(c);
  header.put(checkpoint_format_version);
  header.put(length_);
  header.put(checksum_);
  write_at(0, header.bytes());
  if (options_.kill_half_way) {
    // What a crash half-way through the body would leave.
    if (::ftruncate(fd_, static_cast<off_t>(checkpoint_header_bytes + length_ / 2)) == 0)
      ::fsync(fd_);
    std::raise(SIGKILL);
  }
  // Flushed to the disk before the rename: after a crash the name checkpoint.bin never points
  // at data that did not reach it.
  if (::fsync(fd_) != 0) fail_write(temporary_, "fsync failed");
  const int fd = fd_;
  fd_ = -1;
  if (::close(fd) != 0) fail_write(temporary_, "close failed");
  if (::rename(temporary_.c_str(), file_.c_str()) != 0) fail_write(file_, "rename failed");
  sync_directory(file_.parent_path());
}

void write_checkpoint_file(const std::filesystem::path& file, std::uint64_t model_hash,
                           const CheckpointSections& sections,
                           const CheckpointWriteOptions& options) {
  CheckpointWriter writer(file, model_hash, static_cast<std::uint32_t>(sections.size()), options);
  for (const auto& [name, data] : sections) writer.section(name, data);
  writer.commit();
}

ByteReader CheckpointContents::section(const std::string& name) const {
  for (const auto& [section_name, data] : sections)
    if (section_name == name) return ByteReader(data, fmt::format("{}: section '{}'", file, name));
  throw InputError(
      fmt::format("{}: the checkpoint has no section '{}' (damaged, or written by "
                  "another layout of format version {})",
                  file, name, checkpoint_format_version));
}

CheckpointContents::Place CheckpointContents::place(const std::string& name) const {
  const auto it = in_file.find(name);
  if (it == in_file.end())
    throw InputError(
        fmt::format("{}: the checkpoint has no section '{}' (damaged, or written by "
                    "another layout of format version {})",
                    file, name, checkpoint_format_version));
  return it->second;
}

namespace {

// The checkpoint's body, read from the file as it is parsed: a section left in the file is
// stepped over, never read.
class BodyCursor {
 public:
  BodyCursor(std::ifstream& in, const std::string& name, std::uint64_t end)
      : in_(in), name_(name), end_(end) {}

  std::uint64_t at() const { return at_; }
  std::string bytes(std::uint64_t n) {
    check(n);
    std::string out(n, '\0');
    if (n > 0 && !in_.read(out.data(), static_cast<std::streamsize>(n)))
      throw InputError(fmt::format("{}: cannot read the checkpoint", name_));
    at_ += n;
    return out;
  }
  template <class T>
  T number() {
    const std::string raw = bytes(sizeof(T));
    ByteReader reader(raw, name_);
    return reader.get<T>();
  }
  std::string text() { return bytes(number<std::uint64_t>()); }
  void skip(std::uint64_t n) {
    check(n);
    in_.seekg(static_cast<std::streamoff>(n), std::ios::cur);
    at_ += n;
  }

 private:
  void check(std::uint64_t n) const {
    if (n > end_ - at_)
      throw InputError(
          fmt::format("{}: damaged checkpoint (needs {} more bytes at byte {} of its "
                      "contents, has {})",
                      name_, n, at_, end_ - at_));
  }
  std::ifstream& in_;
  const std::string& name_;
  std::uint64_t end_, at_ = checkpoint_header_bytes;
};

// The checksum of the body, read a slice at a time: the checkpoint is never held whole.
std::uint64_t body_checksum(std::ifstream& in, std::uint64_t length) {
  std::string slice(std::size_t{1} << 20, '\0');
  std::uint64_t h = fnv1a_offset_basis;
  in.seekg(static_cast<std::streamoff>(checkpoint_header_bytes));
  for (std::uint64_t left = length; left > 0;) {
    const std::size_t n = static_cast<std::size_t>(std::min<std::uint64_t>(left, slice.size()));
    if (!in.read(slice.data(), static_cast<std::streamsize>(n))) return ~h;
    h = fnv1a_64(std::string_view(slice.data(), n), h);
    left -= n;
  }
  return h;
}

}  // namespace

CheckpointContents read_checkpoint_file(const std::filesystem::path& file, std::uint64_t model_hash,
                                        const std::vector<std::string>& left_in_file) {
  CheckpointContents contents;
  contents.file = file.string();
  const std::string& name = contents.file;
  std::ifstream in(file, std::ios::binary);
  if (!in) throw InputError(fmt::format("{}: cannot open the checkpoint", name));
  in.seekg(0, std::ios::end);
  const auto size = static_cast<std::uint64_t>(in.tellg());
  in.seekg(0);

  if (size < checkpoint_header_bytes)
    throw InputError(fmt::format("{}: truncated checkpoint ({} bytes; its header alone has {})",
                                 name, size, checkpoint_header_bytes));
  std::string head(checkpoint_header_bytes, '\0');
  in.read(head.data(), static_cast<std::streamsize>(head.size()));
  if (head.compare(0, sizeof(checkpoint_magic), checkpoint_magic, sizeof(checkpoint_magic)) != 0)
    throw InputError(fmt::format("{}: not a geompm checkpoint (it does not start with '{}')", name,
                                 std::string(checkpoint_magic, sizeof(checkpoint_magic))));
  ByteReader header(std::string_view(head).substr(sizeof(checkpoint_magic)), name);
  const auto format = header.get<std::uint32_t>();
  if (format != checkpoint_format_version)
    throw InputError(
        fmt::format("{}: checkpoint format version {}; this geompm ({}) reads format version {} "
                    "only: resume with the geompm that wrote it, or run again without --resume",
                    name, format, GEOMPM_VERSION, checkpoint_format_version));
  const auto length = header.get<std::uint64_t>();
  const auto checksum = header.get<std::uint64_t>();
  const std::uint64_t found = size - checkpoint_header_bytes;
  if (found < length)
    throw InputError(fmt::format("{}: truncated checkpoint ({} bytes; its header announces {})",
                                 name, size, checkpoint_header_bytes + length));
  if (found > length)
    throw InputError(fmt::format("{}: damaged checkpoint ({} bytes more than its header announces)",
                                 name, found - length));
  if (const std::uint64_t sum = body_checksum(in, length); sum != checksum)
    throw InputError(
        fmt::format("{}: damaged checkpoint: the checksum of its contents ({}) is not "
                    "the one it was written with ({})",
                    name, fnv1a_hex(sum), fnv1a_hex(checksum)));

  in.clear();
  in.seekg(static_cast<std::streamoff>(checkpoint_header_bytes));
  BodyCursor body(in, name, size);
  contents.geompm_version = body.text();
  contents.model_hash = body.number<std::uint64_t>();
  if (contents.model_hash != model_hash)
    throw InputError(fmt::format(
        "{}: the checkpoint was written for another model (the text of its model file hashed to "
        "{}, this model file's to {}): resume with the model file the run was started with, "
        "unchanged, or run again without --resume",
        name, fnv1a_hex(contents.model_hash), fnv1a_hex(model_hash)));
  const auto count = body.number<std::uint32_t>();
  for (std::uint32_t k = 0; k < count; ++k) {
    std::string section = body.text();
    const auto bytes = body.number<std::uint64_t>();
    if (std::find(left_in_file.begin(), left_in_file.end(), section) != left_in_file.end()) {
      contents.in_file[section] = {body.at(), bytes};
      body.skip(bytes);
    } else {
      contents.sections.emplace_back(std::move(section), body.bytes(bytes));
    }
  }
  if (body.at() != size)
    throw InputError(
        fmt::format("{}: {} bytes left over after reading it (damaged, or written by "
                    "another layout of the same format version)",
                    name, size - body.at()));
  return contents;
}

}  // namespace geompm
