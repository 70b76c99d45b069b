// The processes of a distributed run as the engine sees them (docs/architecture.md, "Distributed
// runs"): who this process is, and the few collective operations the step needs - sums over the
// grid's shared quantities, the exchange of points between processes, the points passed to
// process 0 for a checkpoint. The interface lives in core so that every room may take one
// without knowing MPI; the MPI implementation is the solver room's (solver/petsc_communicator.hpp),
// which links MPI through PETSc. A serial run uses serial_communicator(): one process, every
// operation the identity, no MPI start-up.
//
// Every collective call must be made by every process, in the same order. Results of sums are
// the same bits on every process (reduced on one, then broadcast), so that every process takes
// the same decisions (Newton's convergence, a cut-back) from them.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

#include "geompm/core/types.hpp"

namespace geompm {

class Communicator {
 public:
  virtual ~Communicator() = default;
  virtual int rank() const = 0;
  virtual int size() const = 0;
  bool distributed() const { return size() > 1; }

  /// Sums `values` element by element over the processes, in place.
  virtual void sum(double* values, std::size_t count) const = 0;
  void sum(std::vector<double>& values) const { sum(values.data(), values.size()); }
  /// The largest value per element over the processes, in place.
  virtual void max(int* values, std::size_t count) const = 0;
  virtual void max(double* values, std::size_t count) const = 0;
  /// Whether `value` holds on every process.
  virtual bool all(bool value) const = 0;
  /// Sends outgoing[r] to process r and returns what each process sent to this one (incoming[r]
  /// from process r).
  virtual std::vector<std::string> exchange(const std::vector<std::string>& outgoing) const = 0;
  /// Every process's bytes, in rank order, on every process.
  virtual std::vector<std::string> all_gather(const std::string& mine) const = 0;
  /// Every process's bytes, in rank order, on process 0 (empty elsewhere).
  virtual std::vector<std::string> gather(const std::string& mine) const = 0;
  /// Waits until every process has come here.
  virtual void barrier() const = 0;
  /// Ends every process of the run now, with exit code `code`: the last resort for an error met
  /// by this process alone (core/agreement.hpp), which the others would wait for at their next
  /// collective call.
  [[noreturn]] virtual void abort(int code) const = 0;

  /// Sums a count over the processes.
  Index sum(Index value) const;
  double sum(double value) const;
};

/// One process: rank 0 of 1, every operation the identity.
const Communicator& serial_communicator();

/// Whether this process was started by mpirun/mpiexec or srun with more than one process
/// (from the launcher's environment, without starting MPI): only then does a run start MPI.
bool launched_with_several_processes();

/// This process's rank as its launcher announces it (0 when it was not started by one), known
/// before MPI starts: the errors every process meets in reading the model are said by rank 0.
int launched_rank();

}  // namespace geompm
