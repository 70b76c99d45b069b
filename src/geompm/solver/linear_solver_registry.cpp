// The registry of linear solvers by name. Adding a solver: one file, one line below
// (docs/architecture.md, "Adding a linear solver"); the model reader and
// tests/unit/solver/test_linear_solver_registry.cpp take every registered name.
#include <fmt/format.h>

#include <utility>

#include "geompm/solver/linear_solver.hpp"
#include "geompm/solver/sparse_lu_solver.hpp"
#include "geompm/solver/umfpack_solver.hpp"

namespace geompm {

namespace {

using Creator = std::unique_ptr<LinearSolver> (*)();

// The default first.
const std::vector<std::pair<std::string, Creator>>& registry() {
  static const std::vector<std::pair<std::string, Creator>> entries = {
      {"umfpack", &create_umfpack_solver},
      {"sparse_lu", &create_sparse_lu_solver},
  };
  return entries;
}

}  // namespace

std::vector<std::string> linear_solver_names() {
  std::vector<std::string> names;
  for (const auto& [name, creator] : registry()) names.push_back(name);
  return names;
}

std::unique_ptr<LinearSolver> create_linear_solver(const std::string& name) {
  for (const auto& [registered, creator] : registry())
    if (registered == name) return creator();
  throw std::invalid_argument(fmt::format("unknown linear solver '{}'; known: {}", name,
                                          fmt::join(linear_solver_names(), ", ")));
}

}  // namespace geompm
