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
  void max(double*, std::size_t) const override {}
  bool all(bool value) const override { return value; }
  std::vector<std::string> exchange(const std::vector<std::string>& outgoing) const override {
    return outgoing;
  }
  std::vector<std::string> all_gather(const std::string& mine) const override { return {mine}; }
  std::vector<std::string> gather(const std::string& mine) const override { return {mine}; }
  void barrier() const override {}
  [[noreturn]] void abort(int code) const override { std::exit(code); }
};

// Where a launcher announces the process count and this process's rank: Open MPI's mpirun,
// MPICH's and Slurm's PMI, srun's job step (set for the tasks it starts, whatever MPI plug-in
// carries them).
struct LauncherVariables {
  const char* size;
  const char* rank;
};
constexpr LauncherVariables launchers[] = {{"OMPI_COMM_WORLD_SIZE", "OMPI_COMM_WORLD_RANK"},
                                           {"PMI_SIZE", "PMI_RANK"},
                                           {"SLURM_STEP_NUM_TASKS", "SLURM_PROCID"},
                                           {"MPI_LOCALNRANKS", "MPI_LOCALRANKID"}};

int launched_size() {
  for (const auto& launcher : launchers)
    if (const char* value = std::getenv(launcher.size)) return std::atoi(value);
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

int launched_rank() {
  for (const auto& launcher : launchers)
    if (std::getenv(launcher.size)) {
      const char* rank = std::getenv(launcher.rank);
      return rank ? std::atoi(rank) : 0;
    }
  return 0;
}

}  // namespace geompm
