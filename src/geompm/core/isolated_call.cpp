#include "geompm/core/isolated_call.hpp"

#include <fmt/format.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <cstring>
#include <exception>

#include "geompm/core/error.hpp"

namespace geompm {

namespace {

// The child's answer starts with one of these, followed by the result or the message.
constexpr char answer_result = 'R';
constexpr char answer_input_error = 'I';
constexpr char answer_other_error = 'E';

void write_all(int fd, const std::string& bytes) {
  std::size_t done = 0;
  while (done < bytes.size()) {
    const ssize_t n = ::write(fd, bytes.data() + done, bytes.size() - done);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return;  // the parent has gone; nothing to tell anyone
    done += static_cast<std::size_t>(n);
  }
}

std::string read_all(int fd) {
  std::string bytes;
  char buffer[1 << 16];
  for (;;) {
    const ssize_t n = ::read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return bytes;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
}

// Set by a sanitizer runtime (the fuzz targets' builds), absent otherwise.
extern "C" void __sanitizer_set_death_callback(void (*callback)()) __attribute__((weak));

/// The child dies of what it reads, quietly: with the default action of the signals of a crash,
/// not a sanitizer's or a fuzzer's handler, which would report the child's death as the whole
/// program's (a fuzzer would save the input as a crash of its own).
void die_quietly_on_a_crash() {
  for (int signal : {SIGSEGV, SIGBUS, SIGFPE, SIGILL, SIGABRT}) std::signal(signal, SIG_DFL);
  if (__sanitizer_set_death_callback != nullptr) __sanitizer_set_death_callback(nullptr);
}

[[noreturn]] void run_child(int fd, const std::function<std::string()>& work) {
  die_quietly_on_a_crash();
  std::string answer;
  try {
    answer = answer_result + work();
  } catch (const InputError& error) {
    answer = answer_input_error + std::string(error.what());
  } catch (const std::exception& error) {
    answer = answer_other_error + std::string(error.what());
  } catch (...) {
    answer = answer_other_error + std::string("an unknown exception");
  }
  write_all(fd, answer);
  ::close(fd);
  // No exit handlers: they belong to the parent (MPI, PETSc, open output files).
  ::_exit(0);
}

int wait_for(pid_t child) {
  int status = 0;
  while (::waitpid(child, &status, 0) < 0)
    if (errno != EINTR) return -1;
  return status;
}

std::string how_it_ended(int status) {
  if (status == -1) return "it could not be waited for";
  if (WIFSIGNALED(status))
    return fmt::format("signal {}, {}", WTERMSIG(status), ::strsignal(WTERMSIG(status)));
  if (WIFEXITED(status)) return fmt::format("exit code {} without an answer", WEXITSTATUS(status));
  return "it ended without an answer";
}

}  // namespace

std::string call_isolated(const std::string& what, const std::function<std::string()>& work) {
  int fds[2];
  if (::pipe(fds) != 0) return work();  // no pipe: read in this process, unprotected
  const pid_t child = ::fork();
  if (child < 0) {
    ::close(fds[0]);
    ::close(fds[1]);
    return work();  // no process to spare: the same, unprotected
  }
  if (child == 0) {
    ::close(fds[0]);
    run_child(fds[1], work);
  }
  ::close(fds[1]);
  const std::string answer = read_all(fds[0]);
  ::close(fds[0]);
  const int status = wait_for(child);
  const bool answered = !answer.empty() && status != -1 && WIFEXITED(status);
  if (!answered)
    throw InputError(
        fmt::format("{}: the reader crashed on it ({}); the file is damaged or not "
                    "what its header says",
                    what, how_it_ended(status)));
  const std::string rest = answer.substr(1);
  switch (answer.front()) {
    case answer_result:
      return rest;
    case answer_input_error:
      throw InputError(rest);
    default:
      throw InputError(fmt::format("{}: cannot be read ({})", what, rest));
  }
}

}  // namespace geompm
