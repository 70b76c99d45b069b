// The processes of an mpi test executable (tests/mpi/*.cpp, under mpirun): its main
// (mpi_main.cpp) starts MPI through PETSc, runs every test on every process (the collectives need
// all of them), lets process 0 alone report, and fails if a test failed on any process.
#pragma once

#include "geompm/core/communicator.hpp"

namespace geompm::testing {

/// Every process of the run.
const Communicator& world();

}  // namespace geompm::testing
