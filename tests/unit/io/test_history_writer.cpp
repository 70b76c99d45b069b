// The history writer under faults: a file that cannot be written (a full disk: /dev/full; a file
// size limit reached mid-run) is a RunError naming the file, never a silent loss, and the file is
// left ending with its last whole row. Both faults act on root as on any user.
#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "geompm/core/error.hpp"
#include "geompm/io/history_writer.hpp"

namespace {

namespace fs = std::filesystem;

std::string read_text(const fs::path& file) {
  std::ifstream in(file, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(HistoryWriter, AFullDiskIsARunErrorNamingTheFile) {
  if (!fs::exists("/dev/full")) GTEST_SKIP() << "no /dev/full";
  try {
    geompm::HistoryWriter writer("/dev/full", {"time", "force"});
    FAIL() << "writing the header to /dev/full did not fail";
  } catch (const geompm::RunError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("cannot write /dev/full"), std::string::npos) << what;
    EXPECT_NE(what.find("No space left on device"), std::string::npos) << what;
  }
}

// A file size limit (RLIMIT_FSIZE, with SIGXFSZ ignored so that the write fails with EFBIG) fills
// the "disk" after a few rows; in a child process, so that the limit stays there.
TEST(HistoryWriter, AWriteThatFailsMidRunThrowsAndLeavesWholeRows) {
  const fs::path file =
      fs::temp_directory_path() / ("geompm_history_" + std::to_string(getpid()) + ".csv");
  fs::remove(file);
  const pid_t child = fork();
  ASSERT_GE(child, 0);
  if (child == 0) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{100, 100};  // bytes: the header and a few rows
    if (setrlimit(RLIMIT_FSIZE, &limit) != 0) _exit(10);
    try {
      geompm::HistoryWriter writer(file, {"time", "force"});
      for (int k = 0; k < 100; ++k) writer.append({0.125 * k, 1e3 * k + 0.5});
      _exit(11);  // never failed
    } catch (const geompm::RunError& e) {
      const std::string what = e.what();
      _exit(what.find("cannot write " + file.string()) != std::string::npos ? 0 : 12);
    } catch (...) {
      _exit(13);
    }
  }
  int status = 0;
  ASSERT_EQ(waitpid(child, &status, 0), child);
  ASSERT_TRUE(WIFEXITED(status)) << "the writer was killed by signal " << WTERMSIG(status);
  EXPECT_EQ(WEXITSTATUS(status), 0) << "10: setrlimit failed, 11: no error, 12: wrong message, "
                                       "13: not a RunError";
  const std::string text = read_text(file);
  EXPECT_GT(text.size(), 12u) << "the header and rows before the limit are kept";
  ASSERT_FALSE(text.empty());
  EXPECT_EQ(text.back(), '\n') << "the history ends mid-row:\n" << text;
  fs::remove(file);
}

}  // namespace
