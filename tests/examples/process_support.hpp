// Support for the end-to-end tests that interrupt geompm: starting it as a child process (with
// extra environment variables), killing it with SIGKILL at a chosen moment, and waiting for it.
//
// Header-only (every function `inline`), like cli_support.hpp.
#pragma once

#include <fcntl.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <utility>
#include <vector>

#include "cli_support.hpp"

extern char** environ;

namespace geompm::testing {

/// A geompm started in the background (fork + exec), stdout and stderr into files.
class GeompmProcess {
 public:
  GeompmProcess(const std::vector<std::string>& args, const std::filesystem::path& cwd,
                const std::filesystem::path& capture,
                const std::vector<std::pair<std::string, std::string>>& environment = {})
      : out_(capture / "background_stdout.txt"), err_(capture / "background_stderr.txt") {
    std::vector<std::string> env;
    for (char** e = environ; *e; ++e) env.emplace_back(*e);
    for (const auto& [name, value] : environment) env.push_back(name + "=" + value);
    std::vector<std::string> argv = {GEOMPM_BINARY};
    argv.insert(argv.end(), args.begin(), args.end());
    pid_ = ::fork();
    if (pid_ == 0) {
      // The child: only async-signal-safe calls until exec.
      if (::chdir(cwd.c_str()) != 0) ::_exit(127);
      const int in = ::open("/dev/null", O_RDONLY);
      const int out = ::open(out_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      const int err = ::open(err_.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
      if (in < 0 || out < 0 || err < 0) ::_exit(127);
      ::dup2(in, 0);
      ::dup2(out, 1);
      ::dup2(err, 2);
      std::vector<char*> a, e;
      for (auto& s : argv) a.push_back(s.data());
      a.push_back(nullptr);
      for (auto& s : env) e.push_back(s.data());
      e.push_back(nullptr);
      ::execve(a[0], a.data(), e.data());
      ::_exit(127);
    }
  }
  ~GeompmProcess() {
    if (pid_ > 0 && !waited_) {
      ::kill(pid_, SIGKILL);
      wait();
    }
  }
  GeompmProcess(const GeompmProcess&) = delete;
  GeompmProcess& operator=(const GeompmProcess&) = delete;

  bool started() const { return pid_ > 0; }
  /// True while the process has not ended (it is not waited for).
  bool running() {
    if (waited_) return false;
    int status = 0;
    const pid_t done = ::waitpid(pid_, &status, WNOHANG);
    if (done == pid_) record(status);
    return !waited_;
  }
  /// Sends `signal_number` (SIGINT: Ctrl-C at a terminal).
  void signal(int signal_number) {
    if (!waited_) ::kill(pid_, signal_number);
  }
  /// SIGKILL, as a crash, a power cut or a batch system's hard limit would end it.
  void kill() {
    if (!waited_) ::kill(pid_, SIGKILL);
  }
  /// Waits for the end; what it printed and how it ended.
  CommandResult wait() {
    if (!waited_) {
      int status = 0;
      while (::waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
      }
      record(status);
    }
    result_.out = read_text(out_);
    result_.err = read_text(err_);
    return result_;
  }

 private:
  void record(int status) {
    waited_ = true;
    if (WIFEXITED(status)) {
      result_.exited = true;
      result_.exit_code = WEXITSTATUS(status);
    } else if (WIFSIGNALED(status)) {
      result_.signal = WTERMSIG(status);
    }
  }

  std::filesystem::path out_, err_;
  pid_t pid_ = -1;
  bool waited_ = false;
  CommandResult result_;
};

}  // namespace geompm::testing
