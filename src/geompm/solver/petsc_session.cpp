#include "geompm/solver/petsc_session.hpp"

#include <fmt/format.h>

#include <mutex>
#include <stdexcept>

#include "geompm/solver/linear_solver.hpp"

namespace geompm::petsc {

namespace {

// PETSc's message of the last error, kept by the error handler for check(): PETSc's default
// handler prints a traceback to stderr instead, and its codes alone say little.
thread_local std::string last_message;

PetscErrorCode keep_message(MPI_Comm, int, const char*, const char*, PetscErrorCode code,
                            PetscErrorType type, const char* message, void*) {
  if (type == PETSC_ERROR_INITIAL) last_message = message ? message : "";
  return code;
}

struct Session {
  std::string options;
  explicit Session(const std::string& given) : options(given) {
    if (PetscInitializeNoArguments() != 0)
      throw std::runtime_error("PETSc: PetscInitialize failed");
    PetscPushErrorHandler(&keep_message, nullptr);
    if (!options.empty() && PetscOptionsInsertString(nullptr, options.c_str()) != 0)
      throw std::invalid_argument(
          fmt::format("PETSc options '{}' not understood: {}", options, last_message));
  }
  ~Session() { PetscFinalize(); }
  Session(const Session&) = delete;
  Session& operator=(const Session&) = delete;
};

std::mutex session_mutex;

const Session& session(const std::string& options) {
  // A function-local static: built once, destroyed (PetscFinalize, MPI_Finalize) at exit.
  static Session instance(options);
  return instance;
}

}  // namespace

void initialise(const std::string& options) {
  const std::lock_guard lock(session_mutex);
  const Session& s = session(options);
  if (!options.empty() && options != s.options)
    throw std::invalid_argument(fmt::format(
        "PETSc options '{}' given after PETSc was initialised with '{}'", options, s.options));
}

void check(PetscErrorCode code, const char* what) {
  if (code == 0) return;
  const char* text = nullptr;
  PetscErrorMessage(code, &text, nullptr);
  throw LinearSolverFailure(fmt::format(
      "PETSc: {}: {}", what, last_message.empty() ? (text ? text : "error") : last_message));
}

std::string unused_options() {
  PetscInt count = 0;
  char** names = nullptr;
  char** values = nullptr;
  if (PetscOptionsLeftGet(nullptr, &count, &names, &values) != 0) return {};
  std::string unused;
  for (PetscInt i = 0; i < count; ++i)
    unused += (unused.empty() ? "-" : " -") + std::string(names[i]);
  PetscOptionsLeftRestore(nullptr, &count, &names, &values);
  return unused;
}

}  // namespace geompm::petsc
