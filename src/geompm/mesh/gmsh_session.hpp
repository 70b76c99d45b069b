// One use of the Gmsh API at a time. Gmsh keeps its models and options in global state, so every
// call into it from geompm goes through a GmshSession: it locks a process-wide mutex, initialises
// Gmsh without reading command-line arguments or configuration files, silences its terminal
// output, and finalises it when the session ends (also when an exception leaves the scope).
// Gmsh sets the C numeric locale to "C" and leaves it so; the session puts it back.
#pragma once

#include <mutex>
#include <string>

namespace geompm {

class GmshSession {
 public:
  GmshSession();
  ~GmshSession();
  GmshSession(const GmshSession&) = delete;
  GmshSession& operator=(const GmshSession&) = delete;

 private:
  std::unique_lock<std::mutex> lock_;
  std::string numeric_locale_;  // LC_NUMERIC before Gmsh changed it
};

/// Call inside a catch (...) block: the text of what Gmsh (or anything else) threw. Gmsh 4.8
/// throws std::string with its last error; newer versions throw std::exception.
std::string current_exception_message();

}  // namespace geompm
