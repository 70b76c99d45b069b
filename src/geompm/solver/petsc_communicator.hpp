// The processes of an mpirun/srun run as a Communicator (core/communicator.hpp), over PETSc's
// MPI_COMM_WORLD. MPI is started through PETSc's session (petsc_session.cpp), so that the
// distributed linear solver and the step share one start-up and one finalisation.
#pragma once

#include <memory>
#include <string>

#include "geompm/core/communicator.hpp"

namespace geompm {

/// Starts PETSc (and MPI) with the model's expert options `petsc_options` if it is not yet, and
/// returns the communicator of every process of the run.
std::unique_ptr<Communicator> mpi_world_communicator(const std::string& petsc_options);

}  // namespace geompm
