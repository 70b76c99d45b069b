// The checkpoint file: a versioned binary container of named sections (docs/checkpoint-format.md).
// It knows bytes only; what each section holds is written and read by the owner of that state
// (analysis/simulation_state.cpp). Written atomically (a temporary file, flushed to disk, renamed
// over the last checkpoint), so a run killed at any moment leaves the previous checkpoint or the
// new one, never half of one; read with every check a damaged or foreign file needs.
#pragma once

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "geompm/core/byte_archive.hpp"

namespace geompm {

inline constexpr char checkpoint_magic[8] = {'G', 'E', 'O', 'M', 'P', 'M', 'C', 'K'};
inline constexpr std::uint32_t checkpoint_format_version = 5;
/// Magic, format version, body length and checksum come before the body.
inline constexpr std::size_t checkpoint_header_bytes = 8 + 4 + 8 + 8;

/// Named sections, in the order they are written.
using CheckpointSections = std::vector<std::pair<std::string, std::string>>;

struct CheckpointWriteOptions {
  /// Test only: kill the process (SIGKILL) after half of the temporary file is written, as a
  /// crash or a power cut in the middle of a checkpoint would.
  bool kill_half_way = false;
};

/// The temporary file a checkpoint is written to before the rename: `file` + ".tmp".
std::filesystem::path checkpoint_temporary(const std::filesystem::path& file);

/// A checkpoint written as it is made: the body's bytes are passed in order, a large section in
/// pieces, so that the writer never holds the whole body (a distributed run's points reach
/// process 0 a slice at a time: points/streamed_points.hpp). Atomic: the body goes to the
/// temporary file, the header (the body's length and checksum, known at the end) is written
/// last, the file is flushed to the disk and renamed over `file` by commit(). Each write that
/// fails (a full disk) throws RunError; the temporary file is left then, as after a crash.
class CheckpointWriter {
 public:
  /// Creates the temporary file for a body of `sections` sections.
  CheckpointWriter(std::filesystem::path file, std::uint64_t model_hash, std::uint32_t sections,
                   CheckpointWriteOptions options = {});
  ~CheckpointWriter();
  CheckpointWriter(const CheckpointWriter&) = delete;
  CheckpointWriter& operator=(const CheckpointWriter&) = delete;

  /// A whole section.
  void section(const std::string& name, std::string_view bytes);
  /// A section of `length` bytes, passed by add() in pieces (in order).
  void begin_section(const std::string& name, std::uint64_t length);
  void add(std::string_view bytes);
  /// Once every section is written: the header, the flush to disk and the rename.
  void commit();

 private:
  void body(std::string_view bytes);  // buffered, hashed
  void flush();
  void write_at(std::uint64_t offset, std::string_view bytes);

  std::filesystem::path file_, temporary_;
  CheckpointWriteOptions options_;
  int fd_ = -1;
  std::string buffer_;
  std::uint64_t length_ = 0, checksum_;
  std::uint32_t sections_left_;
  std::uint64_t section_left_ = 0;  // bytes the section begun still expects
};

/// Writes the checkpoint atomically (CheckpointWriter). Throws RunError if the file cannot be
/// written (a full disk).
void write_checkpoint_file(const std::filesystem::path& file, std::uint64_t model_hash,
                           const CheckpointSections& sections,
                           const CheckpointWriteOptions& options = {});

struct CheckpointContents {
  /// Where a section left in the file lies in it: its bytes from `offset`, `length` of them.
  struct Place {
    std::uint64_t offset = 0, length = 0;
  };

  std::string file;            // as given, for messages
  std::string geompm_version;  // of the geompm that wrote it
  std::uint64_t model_hash = 0;
  CheckpointSections sections;           // those read
  std::map<std::string, Place> in_file;  // those left in the file

  /// A reader of the section `name`; throws InputError if the checkpoint has none.
  ByteReader section(const std::string& name) const;
  /// Where the section `name` left in the file lies; throws InputError if the checkpoint has none.
  Place place(const std::string& name) const;
};

/// Reads and checks a checkpoint: throws InputError naming the file and what is wrong when it is
/// missing, truncated, not a checkpoint, of another format version, damaged (checksum) or written
/// for a model whose text hashes otherwise than `model_hash`. The sections named in
/// `left_in_file` are not read, only found (`in_file`): a reader takes what it needs of them from
/// the file (a distributed run's points, analysis/simulation_state.cpp). The file is read a slice
/// at a time, never held whole.
CheckpointContents read_checkpoint_file(const std::filesystem::path& file, std::uint64_t model_hash,
                                        const std::vector<std::string>& left_in_file = {});

}  // namespace geompm
