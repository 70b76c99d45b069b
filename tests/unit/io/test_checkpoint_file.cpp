// The checkpoint container (io/checkpoint_file, docs/checkpoint-format.md) and the byte archive
// its sections are written with (core/byte_archive): what is written reads back bit for bit, and
// every way a file can be unusable (missing, truncated anywhere, any byte changed, another
// model, another format version) gives an InputError naming the file and the problem.
#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "geompm/core/byte_archive.hpp"
#include "geompm/core/error.hpp"
#include "geompm/core/fnv1a.hpp"
#include "geompm/core/types.hpp"
#include "geompm/io/checkpoint_file.hpp"

namespace geompm {
namespace {

namespace fs = std::filesystem;

std::string read_bytes(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}
void write_bytes(const fs::path& file, const std::string& bytes) {
  std::ofstream(file, std::ios::binary | std::ios::trunc) << bytes;
}

// The message of the InputError reading `file` throws, or a failure.
std::string read_error(const fs::path& file, std::uint64_t hash) {
  try {
    read_checkpoint_file(file, hash);
  } catch (const InputError& e) {
    return e.what();
  } catch (const std::exception& e) {
    ADD_FAILURE() << "expected an InputError, got: " << e.what();
    return "";
  }
  ADD_FAILURE() << "expected an InputError, the checkpoint was accepted";
  return "";
}

TEST(ByteArchive, ReadsBackBitForBit) {
  ByteWriter out;
  const double awkward[] = {0.1, -0.0, std::numeric_limits<double>::denorm_min(),
                            std::numeric_limits<double>::quiet_NaN(), 1e308};
  for (double v : awkward) out.put(v);
  out.put(std::int32_t{-7});
  out.put(std::string("phase, with text"));
  const Vec3 x(1.0 / 3.0, 2.0, -5e-300);
  Mat3 m;
  m << 1, 2, 3, 4, 5, 6, 7, 8, 9.5;
  out.put(x);
  out.put(m);
  out.put(std::vector<Vec3>{x, 2 * x});
  out.put(std::vector<std::uint64_t>{1, 2, 3});
  out.put(std::map<std::string, Vec3>{{"a", x}, {"b", -x}});
  out.put(std::vector<std::pair<std::int32_t, Vec3>>{{4, x}});
  out.put(std::array<double, 4>{1, 2, 3, 4});

  ByteReader in(out.bytes(), "test");
  for (double v : awkward) {
    const double back = in.get<double>();
    EXPECT_EQ(std::memcmp(&back, &v, sizeof v), 0) << v;
  }
  EXPECT_EQ(in.get<std::int32_t>(), -7);
  EXPECT_EQ(in.get<std::string>(), "phase, with text");
  EXPECT_EQ(in.get<Vec3>(), x);
  EXPECT_EQ(in.get<Mat3>(), m);
  EXPECT_EQ((in.get<std::vector<Vec3>>()), (std::vector<Vec3>{x, 2 * x}));
  EXPECT_EQ((in.get<std::vector<std::uint64_t>>()), (std::vector<std::uint64_t>{1, 2, 3}));
  const auto map = in.get<std::map<std::string, Vec3>>();
  ASSERT_EQ(map.size(), 2u);
  EXPECT_EQ(map.at("b"), -x);
  const auto pairs = in.get<std::vector<std::pair<std::int32_t, Vec3>>>();
  ASSERT_EQ(pairs.size(), 1u);
  EXPECT_EQ(pairs[0].first, 4);
  EXPECT_EQ(pairs[0].second, x);
  EXPECT_EQ((in.get<std::array<double, 4>>()), (std::array<double, 4>{1, 2, 3, 4}));
  EXPECT_NO_THROW(in.expect_end());
}

TEST(ByteArchive, RefusesToReadPastTheEndOrBeyondACount) {
  ByteWriter out;
  out.put(std::vector<double>{1, 2, 3});
  const std::string bytes = out.bytes();
  // Cut short: the count promises more doubles than are left.
  ByteReader cut(std::string_view(bytes).substr(0, bytes.size() - 1), "file.bin: section 's'");
  try {
    cut.get<std::vector<double>>();
    FAIL() << "read past the end";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("file.bin: section 's': ends too early"),
              std::string::npos)
        << e.what();
  }
  // A damaged count must not allocate what it says.
  ByteWriter huge;
  huge.put(std::uint64_t{1} << 60);
  ByteReader in(huge.bytes(), "huge");
  EXPECT_THROW(in.get<std::vector<Vec3>>(), InputError);
  // Bytes left over are an error too.
  ByteReader rest(bytes, "rest");
  rest.get<std::uint64_t>();
  EXPECT_THROW(rest.expect_end(), InputError);
}

TEST(Fnv1a, MatchesThePublishedVectorsAndSeesEveryByte) {
  EXPECT_EQ(fnv1a_64(""), 0xcbf29ce484222325ull);
  EXPECT_EQ(fnv1a_64("a"), 0xaf63dc4c8601ec8cull);
  EXPECT_EQ(fnv1a_hex(fnv1a_64("foobar")), "85944171f73967e8");
  const std::string text = "title: Column\nphases: []\n";
  for (std::size_t k = 0; k < text.size(); ++k)
    for (int bit = 0; bit < 8; ++bit) {
      std::string changed = text;
      changed[k] = static_cast<char>(changed[k] ^ (1 << bit));
      EXPECT_NE(fnv1a_64(changed), fnv1a_64(text)) << k << " " << bit;
    }
}

class CheckpointFile : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("geompm_checkpoint_file_" + std::to_string(getpid()));
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  CheckpointSections sections() const {
    ByteWriter points;
    points.put(std::vector<Vec3>(5, Vec3(1, 2, 3)));
    return {{"run", std::string("\x01\x02\x03", 3)}, {"points", points.bytes()}, {"empty", ""}};
  }

  fs::path dir_;
  static constexpr std::uint64_t kHash = 0x0123456789abcdefull;
};

TEST_F(CheckpointFile, ReadsBackWhatWasWritten) {
  const fs::path file = dir_ / "checkpoint.bin";
  write_checkpoint_file(file, kHash, sections());
  EXPECT_FALSE(fs::exists(checkpoint_temporary(file))) << "the temporary is renamed";
  const CheckpointContents contents = read_checkpoint_file(file, kHash);
  EXPECT_EQ(contents.geompm_version, GEOMPM_VERSION);
  EXPECT_EQ(contents.model_hash, kHash);
  EXPECT_EQ(contents.sections, sections());
  ByteReader points = contents.section("points");
  EXPECT_EQ(points.get<std::vector<Vec3>>().size(), 5u);
  try {
    contents.section("phase");
    FAIL() << "no such section";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("no section 'phase'"), std::string::npos);
  }
  // The header: magic, format version, then the body's length and checksum.
  const std::string bytes = read_bytes(file);
  EXPECT_EQ(bytes.substr(0, 8), "GEOMPMCK");
  EXPECT_EQ(bytes[8], static_cast<char>(checkpoint_format_version));
  std::uint64_t length = 0;
  std::memcpy(&length, bytes.data() + 12, 8);
  EXPECT_EQ(length + checkpoint_header_bytes, bytes.size());
}

TEST_F(CheckpointFile, ASectionPassedInPiecesIsTheWholeOne) {
  // The writer a distributed run streams its points through (analysis/simulation_state.cpp):
  // pieces of every size, some larger than its buffer, make the file write_checkpoint_file
  // writes of the whole sections (checksum included).
  CheckpointSections whole = sections();
  std::string large(3'000'000, '\0');
  for (std::size_t i = 0; i < large.size(); ++i) large[i] = static_cast<char>(i * 131 % 251);
  whole[1].second = large;
  write_checkpoint_file(dir_ / "whole.bin", kHash, whole);
  CheckpointWriter writer(dir_ / "pieces.bin", kHash, 3);
  writer.section(whole[0].first, whole[0].second);
  writer.begin_section(whole[1].first, large.size());
  for (std::size_t at = 0, piece = 1; at < large.size(); at += piece, piece *= 3)
    writer.add(std::string_view(large).substr(at, piece));
  writer.begin_section(whole[2].first, 0);
  writer.commit();
  EXPECT_TRUE(read_bytes(dir_ / "pieces.bin") == read_bytes(dir_ / "whole.bin"));
  EXPECT_EQ(read_checkpoint_file(dir_ / "pieces.bin", kHash).sections, whole);
}

TEST_F(CheckpointFile, AWriterGivenTooManyOrTooFewBytesIsALogicError) {
  {
    CheckpointWriter writer(dir_ / "more.bin", kHash, 1);
    writer.begin_section("points", 4);
    EXPECT_THROW(writer.add("five!"), std::logic_error);
  }
  {
    CheckpointWriter writer(dir_ / "fewer.bin", kHash, 2);
    writer.begin_section("points", 4);
    writer.add("abc");
    EXPECT_THROW(writer.begin_section("model", 0), std::logic_error);
    EXPECT_THROW(writer.commit(), std::logic_error);
  }
  // Never renamed: no checkpoint, the temporary left as after a crash.
  EXPECT_FALSE(fs::exists(dir_ / "fewer.bin"));
  EXPECT_TRUE(fs::exists(checkpoint_temporary(dir_ / "fewer.bin")));
}

TEST_F(CheckpointFile, AFileThatCannotBeWrittenIsARunError) {
  // /dev/full: every write fails with ENOSPC, for root too (a full disk).
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  fs::create_symlink("/dev/full", checkpoint_temporary(dir_ / "checkpoint.bin"));
  try {
    write_checkpoint_file(dir_ / "checkpoint.bin", kHash, sections());
    FAIL() << "written on a full disk";
  } catch (const RunError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot write the checkpoint"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("No space left on device"), std::string::npos);
  }
  EXPECT_FALSE(fs::exists(dir_ / "checkpoint.bin"));
}

TEST_F(CheckpointFile, ReplacesTheLastOneAtomically) {
  const fs::path file = dir_ / "checkpoint.bin";
  write_checkpoint_file(file, kHash, sections());
  write_bytes(checkpoint_temporary(file), "half of a checkpoint");  // as a killed run leaves
  CheckpointSections later = sections();
  later[0].second = "later";
  write_checkpoint_file(file, kHash, later);
  EXPECT_EQ(read_checkpoint_file(file, kHash).sections, later);
  EXPECT_FALSE(fs::exists(checkpoint_temporary(file)));
}

TEST_F(CheckpointFile, NamesAMissingFile) {
  const std::string message = read_error(dir_ / "checkpoint.bin", kHash);
  EXPECT_NE(message.find("checkpoint.bin: cannot open"), std::string::npos) << message;
}

TEST_F(CheckpointFile, RefusesATruncatedFileWhereverItIsCut) {
  const fs::path file = dir_ / "checkpoint.bin";
  write_checkpoint_file(file, kHash, sections());
  const std::string bytes = read_bytes(file);
  for (std::size_t size = 0; size < bytes.size(); ++size) {
    write_bytes(file, bytes.substr(0, size));
    const std::string message = read_error(file, kHash);
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
    EXPECT_NE(message.find("truncated checkpoint"), std::string::npos)
        << "cut at " << size << ": " << message;
  }
}

TEST_F(CheckpointFile, RefusesAFileWithAnyByteChanged) {
  const fs::path file = dir_ / "checkpoint.bin";
  write_checkpoint_file(file, kHash, sections());
  const std::string bytes = read_bytes(file);
  for (std::size_t k = 0; k < bytes.size(); ++k) {
    std::string changed = bytes;
    changed[k] = static_cast<char>(changed[k] ^ 0x10);
    write_bytes(file, changed);
    const std::string message = read_error(file, kHash);
    EXPECT_EQ(message.rfind(file.string() + ": ", 0), 0u) << message;
    // Where the byte is says which check finds it.
    const char* expected = k < 8                             ? "not a geompm checkpoint"
                           : k < 12                          ? "checkpoint format version"
                           : k < checkpoint_header_bytes - 8 ? "checkpoint ("  // the length
                                                             : "damaged checkpoint";
    EXPECT_NE(message.find(expected), std::string::npos) << "byte " << k << ": " << message;
  }
}

TEST_F(CheckpointFile, RefusesAnotherModel) {
  const fs::path file = dir_ / "checkpoint.bin";
  write_checkpoint_file(file, kHash, sections());
  const std::string message = read_error(file, kHash + 1);
  EXPECT_NE(message.find("written for another model"), std::string::npos) << message;
  EXPECT_NE(message.find(fnv1a_hex(kHash)), std::string::npos) << message;
}

TEST_F(CheckpointFile, RefusesAnotherFormatVersion) {
  const fs::path file = dir_ / "checkpoint.bin";
  write_checkpoint_file(file, kHash, sections());
  std::string bytes = read_bytes(file);
  const std::uint32_t next = checkpoint_format_version + 1;
  std::memcpy(bytes.data() + 8, &next, sizeof next);
  write_bytes(file, bytes);
  const std::string message = read_error(file, kHash);
  EXPECT_NE(message.find("checkpoint format version " + std::to_string(next) +
                         "; this geompm (" GEOMPM_VERSION ") reads format version " +
                         std::to_string(checkpoint_format_version)),
            std::string::npos)
      << message;
}

}  // namespace
}  // namespace geompm
