// PETSc initialised once per process, on the first use of a PETSc solver (a run with UMFPACK never
// pays MPI's start-up, about a second here), and finalised at exit; and PETSc's errors turned
// into exceptions that carry PETSc's own message. Only the PETSc translation units include this.
#pragma once

#include <petscsys.h>

#include <string>

namespace geompm::petsc {

/// Initialises PETSc if it is not yet (idempotent, for the whole process). `options` (PETSc's
/// command-line syntax, "-ksp_type gmres -pc_gamg_threshold 0.02") go into its options database
/// then; later calls must pass the same options or none. PETSc also reads the environment
/// variable PETSC_OPTIONS.
void initialise(const std::string& options);

/// Throws LinearSolverFailure("PETSc: <what>: <PETSc's message>") if `code` is an error.
void check(PetscErrorCode code, const char* what);

/// The expert options given to initialise() that no PETSc object has used (misspelt, or meant for
/// another solver), space-separated; empty if all were used.
std::string unused_options();

/// Puts `key value` into PETSc's options database unless the user gave the key: a default that
/// experts may override, for objects a solver does not create itself (a field split's blocks,
/// multigrid levels).
void set_default(const char* key, const char* value);

}  // namespace geompm::petsc
