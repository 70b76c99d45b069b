// The run's progress on the log: one line that rewrites itself on a terminal, or a line every few
// seconds into a log file (and always for the events that matter, such as a cut-back).
#pragma once

#include <chrono>
#include <iosfwd>
#include <string>

namespace geompm {

/// "hh:mm:ss" of a number of seconds (an ETA, a wall time).
std::string format_duration(double seconds);

class ProgressLine {
 public:
  ProgressLine(std::ostream* out, bool enabled);
  void update(const std::string& text, bool force = false);
  /// Ends the rewritten line on a terminal, so that what follows starts on a line of its own.
  void finish();

 private:
  std::ostream* out_;
  bool tty_;
  std::chrono::steady_clock::time_point last_{};
};

}  // namespace geompm
