#include "geompm/solver/petsc_session.hpp"

#include <fmt/format.h>

#include <mutex>
#include <set>
#include <sstream>

#include "geompm/core/error.hpp"
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
      throw InputError(fmt::format("PETSc options '{}' not understood: {}", options, last_message));
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

static const std::string& session_options() { return session("").options; }

void initialise(const std::string& options) {
  const std::lock_guard lock(session_mutex);
  const Session& s = session(options);
  if (!options.empty() && options != s.options)
    throw InputError(fmt::format("PETSc options '{}' given after PETSc was initialised with '{}'",
                                 options, s.options));
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
  // Only the user's: the defaults the solvers put in the database (set_default) for another
  // solver's objects are not a mistake.
  std::istringstream given(session_options());
  std::set<std::string> user;
  for (std::string word; given >> word;)
    if (word.size() > 1 && word[0] == '-') user.insert(word.substr(1));
  std::string unused;
  for (PetscInt i = 0; i < count; ++i)
    if (user.count(names[i])) unused += (unused.empty() ? "-" : " -") + std::string(names[i]);
  PetscOptionsLeftRestore(nullptr, &count, &names, &values);
  return unused;
}

void set_default(const char* key, const char* value) {
  PetscBool given = PETSC_FALSE;
  check(PetscOptionsHasName(nullptr, nullptr, key, &given), "PetscOptionsHasName");
  if (!given) check(PetscOptionsSetValue(nullptr, key, value), "PetscOptionsSetValue");
}

}  // namespace geompm::petsc
