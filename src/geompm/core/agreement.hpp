// How the processes of a distributed run end together when something goes wrong on one of them
// (docs/architecture.md, "Distributed runs"). An error thrown on one process only would leave the
// others waiting at their next collective call for ever, so:
//
//  - where the serial code may throw on one process (the step's local work on its points, the
//    files process 0 writes), the work runs inside together(): every process then says in one
//    reduction whether its work went wrong, and if any did, every process throws that process's
//    error (the same kind, the same message). An error that every process throws at the same
//    point is marked met_by_all(): each process ends the run as a serial run ends it, and
//    process 0 says why, once.
//  - any other error of a distributed run is this process's alone: end_alone() prints it (naming
//    the process) and ends every process with the serial run's exit code, a last resort that
//    never leaves a process waiting.
#pragma once

#include <exception>
#include <functional>
#include <string>

#include "geompm/core/communicator.hpp"
#include "geompm/core/error.hpp"

namespace geompm {

/// The mark of an error thrown by every process of a run at the same point of it.
class MetByAll {
 public:
  virtual ~MetByAll() = default;
};

/// `Error` (InputError, RunError, ...) thrown by every process together.
template <class Error>
class Shared final : public Error, public MetByAll {
 public:
  using Error::Error;
};

/// Whether every process of the run has thrown `error` at the same point (always so on one
/// process).
bool met_by_all(const std::exception& error, const Communicator& processes);

/// Runs `work` on this process; in a distributed run, every process then learns in one
/// reduction whether the work threw on any process, and if it did, every process throws the
/// error of the lowest such process: a Shared<InputError>, Shared<RunError> or (any other
/// exception) an internal error with its message. Returns whether `work` returned true on every
/// process. Collective; `work` itself must make no collective call (a process that threw would
/// not make it). On one process it only runs `work`.
bool together_all(const Communicator& processes, const std::function<bool()>& work);
/// together_all for work without a verdict.
void together(const Communicator& processes, const std::function<void()>& work);

/// The exit code of the command line for `error` (app/main.cpp): 2 bad input, 3 the run
/// stopped, 4 an internal error.
int exit_code(const std::exception& error);
/// The line the command line prints for `error`: "error: ...", "run stopped: ..." or
/// "internal error: ...".
std::string describe_error(const std::exception& error);

/// An error of a distributed run met by this process alone: prints it to the standard error,
/// naming the process, and ends every process with exit_code(error).
[[noreturn]] void end_alone(const std::exception& error, const Communicator& processes);

/// Test only: GEOMPM_TEST_FAULT=<rank>:<site> throws a RunError on process <rank> the first time
/// the run passes `site` ("step": in the step's work on the points, inside together();
/// "between_steps": outside it), as a fault met by one process alone would
/// (tests/mpi/test_faults.py).
void inject_test_fault(const Communicator& processes, const char* site);

}  // namespace geompm
