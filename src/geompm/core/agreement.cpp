#include "geompm/core/agreement.hpp"

#include <fmt/format.h>

#include <cstdlib>
#include <iostream>
#include <set>

namespace geompm {

namespace {

// An error as one process tells the others: its kind (I input, R run, X internal) and message;
// empty when the work went well.
std::string told(const std::exception_ptr& failure) {
  try {
    std::rethrow_exception(failure);
  } catch (const InputError& e) {
    return std::string("I") + e.what();
  } catch (const RunError& e) {
    return std::string("R") + e.what();
  } catch (const std::exception& e) {
    return std::string("X") + e.what();
  } catch (...) {
    return "Xan exception of an unknown type";
  }
}

[[noreturn]] void throw_told(const std::string& error) {
  const std::string message = error.substr(1);
  if (error.front() == 'I') throw Shared<InputError>(message);
  if (error.front() == 'R') throw Shared<RunError>(message);
  throw Shared<std::runtime_error>(message);
}

}  // namespace

bool met_by_all(const std::exception& error, const Communicator& processes) {
  return !processes.distributed() || dynamic_cast<const MetByAll*>(&error) != nullptr;
}

bool together_all(const Communicator& processes, const std::function<bool()>& work) {
  if (!processes.distributed()) return work();
  // 0 the work went well, 1 it returned false, 2 it threw: the largest over the processes.
  int outcome = 0;
  std::string mine;
  try {
    outcome = work() ? 0 : 1;
  } catch (...) {
    outcome = 2;
    mine = told(std::current_exception());
  }
  processes.max(&outcome, 1);
  if (outcome < 2) return outcome == 0;
  // Only when something went wrong: what, from every process; the lowest one that failed says.
  for (const std::string& error : processes.all_gather(mine))
    if (!error.empty()) throw_told(error);
  throw std::logic_error("together: a failure that no process reported");
}

void together(const Communicator& processes, const std::function<void()>& work) {
  together_all(processes, [&] {
    work();
    return true;
  });
}

int exit_code(const std::exception& error) {
  if (dynamic_cast<const InputError*>(&error)) return 2;
  if (dynamic_cast<const RunError*>(&error)) return 3;
  return 4;
}

std::string describe_error(const std::exception& error) {
  switch (exit_code(error)) {
    case 2:
      return std::string("error: ") + error.what();
    case 3:
      return std::string("run stopped: ") + error.what();
    default:
      return std::string("internal error: ") + error.what();
  }
}

void end_alone(const std::exception& error, const Communicator& processes) {
  std::cerr << fmt::format(
                   "\nprocess {} of {}: {}\n(met by this process alone: every process is "
                   "stopped)\n",
                   processes.rank(), processes.size(), describe_error(error))
            << std::flush;
  processes.abort(exit_code(error));
}

void inject_test_fault(const Communicator& processes, const char* site) {
  static const std::string fault = [] {
    const char* value = std::getenv("GEOMPM_TEST_FAULT");
    return std::string(value ? value : "");
  }();
  if (fault.empty() || fault != fmt::format("{}:{}", processes.rank(), site)) return;
  static std::set<std::string> met;
  if (!met.insert(site).second) return;
  throw RunError(
      fmt::format("a test fault (GEOMPM_TEST_FAULT={}) on process {}", fault, processes.rank()));
}

}  // namespace geompm
