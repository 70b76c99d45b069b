#include "geompm/core/communicator.hpp"

#include <cstdlib>

namespace geompm {

namespace {

class SerialCommunicator final : public Communicator {
 public:
  int rank() const override { return 0; }
  int size() const override { return 1; }
  void sum(double*, std::size_t) const override {}
  void max(int*, std::size_t) const override {}
  bool all(bool value) const override { return value; }
  std::vector<std::string> exchange(const std::vector<std::string>& outgoing) const override {
    return outgoing;
  }
  std::vector<std::string> all_gather(const std::string& mine) const override { return {mine}; }
  std::vector<std::string> gather(const std::string& mine) const override { return {mine}; }
  void barrier() const override {}
};

// The process count a launcher announces: Open MPI's mpirun, MPICH's and Slurm's PMI, srun's
// job step (set for the tasks it starts, whatever MPI plug-in carries them).
int launched_size() {
  for (const char* name :
       {"OMPI_COMM_WORLD_SIZE", "PMI_SIZE", "SLURM_STEP_NUM_TASKS", "MPI_LOCALNRANKS"})
    if (const char* value = std::getenv(name)) return std::atoi(value);
  return 1;
}

}  // namespace

Index Communicator::sum(Index value) const {
  double v = static_cast<double>(value);  // exact below 2^53
  sum(&v, 1);
  return static_cast<Index>(v);
}

double Communicator::sum(double value) const {
  sum(&value, 1);
  return value;
}

const Communicator& serial_communicator() {
  static const SerialCommunicator instance;
  return instance;
}

bool launched_with_several_processes() { return launched_size() > 1; }

}  // namespace geompm
