#include "geompm/analysis/progress_line.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <ostream>

namespace geompm {

std::string format_duration(double seconds) {
  const long s = static_cast<long>(seconds + 0.5);
  return fmt::format("{:02d}:{:02d}:{:02d}", s / 3600, (s / 60) % 60, s % 60);
}

ProgressLine::ProgressLine(std::ostream* out, bool enabled)
    : out_(enabled ? out : nullptr), tty_(isatty(fileno(stderr))) {}

void ProgressLine::update(const std::string& text, bool force) {
  if (!out_) return;
  const auto now = std::chrono::steady_clock::now();
  if (tty_) {
    *out_ << "\r" << text << "\033[K" << std::flush;
  } else if (force || now - last_ > std::chrono::seconds(5)) {
    *out_ << text << "\n" << std::flush;
    last_ = now;
  }
}

void ProgressLine::finish() {
  if (out_ && tty_) *out_ << "\n";
}

}  // namespace geompm
