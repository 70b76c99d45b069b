// The registry of linear solvers by name. Adding a solver: one file, one line below
// (docs/architecture.md, "Adding a linear solver"); the model reader and
// tests/unit/solver/test_linear_solver_registry.cpp take every registered name.
#include <fmt/format.h>

#include <cctype>
#include <sstream>
#include <utility>

#include "geompm/solver/auto_solver.hpp"
#include "geompm/solver/linear_solver.hpp"
#include "geompm/solver/petsc_solver.hpp"
#include "geompm/solver/sparse_lu_solver.hpp"
#include "geompm/solver/umfpack_solver.hpp"

namespace geompm {

namespace {

using Creator = std::unique_ptr<LinearSolver> (*)(const LinearSolverOptions&);

struct Entry {
  std::string name;
  Creator create;
  bool petsc;  // reads LinearSolverOptions::petsc_options
};

std::unique_ptr<LinearSolver> umfpack(const LinearSolverOptions&) {
  return create_umfpack_solver();
}
std::unique_ptr<LinearSolver> sparse_lu(const LinearSolverOptions&) {
  return create_sparse_lu_solver();
}

// The default first.
const std::vector<Entry>& registry() {
  static const std::vector<Entry> entries = {
      {"umfpack", &umfpack, false},
      {"sparse_lu", &sparse_lu, false},
      {"auto", &create_auto_solver, true},
      {"petsc_gamg", &create_petsc_gamg_solver, true},
      {"petsc_hypre", &create_petsc_hypre_solver, true},
      {"petsc_mumps", &create_petsc_mumps_solver, true},
  };
  return entries;
}

const Entry& entry(const std::string& name) {
  for (const Entry& e : registry())
    if (e.name == name) return e;
  throw std::invalid_argument(fmt::format("unknown linear solver '{}'; known: {}", name,
                                          fmt::join(linear_solver_names(), ", ")));
}

}  // namespace

std::vector<std::string> linear_solver_names() {
  std::vector<std::string> names;
  for (const Entry& e : registry()) names.push_back(e.name);
  return names;
}

std::unique_ptr<LinearSolver> create_linear_solver(const std::string& name,
                                                   const LinearSolverOptions& options) {
  return entry(name).create(options);
}

bool uses_petsc(const std::string& name) { return entry(name).petsc; }

// PETSc's option syntax: keys "-name" (a letter after the dash), each followed by at most one
// value (which may itself start with a dash only if it is a number, "-1e-3").
std::string petsc_options_error(const std::string& options) {
  std::istringstream words(options);
  std::string word;
  bool key_before = false;
  while (words >> word) {
    const bool key = word.size() > 1 && word[0] == '-' && std::isalpha((unsigned char)word[1]);
    if (!key && !key_before)
      return fmt::format(
          "'{}' is not a PETSc option (expected -key or -key value, e.g. "
          "-ksp_type fgmres)",
          word);
    key_before = key;
  }
  return {};
}

}  // namespace geompm
