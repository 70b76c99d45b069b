#include "geompm/solver/petsc_communicator.hpp"

// PETSc includes MPI without its C++ bindings (which would need libmpi_cxx).
#include <petscsys.h>

#include <fmt/format.h>

#include <cstdlib>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "geompm/core/agreement.hpp"
#include "geompm/core/error.hpp"
#include "geompm/solver/petsc_session.hpp"

namespace geompm {

namespace {

void check(int code, const char* what) {
  if (code != MPI_SUCCESS) throw std::runtime_error(std::string("MPI: ") + what + " failed");
}

// One MPI call carries at most INT_MAX elements, counted and placed by int. The sizes are
// exchanged as 64-bit numbers first, so that every process sees the same total and all stop
// together (an error met by all, core/agreement.hpp), with the reason, where a gather would not
// fit (gathering every point to process 0 for a checkpoint can pass 2 GB at millions of points).
std::vector<int> message_counts(MPI_Comm comm, int size, std::size_t mine, const char* what) {
  const auto own = static_cast<long long>(mine);
  std::vector<long long> sizes(static_cast<std::size_t>(size));
  check(MPI_Allgather(&own, 1, MPI_LONG_LONG, sizes.data(), 1, MPI_LONG_LONG, comm),
        "MPI_Allgather");
  const long long total = std::accumulate(sizes.begin(), sizes.end(), 0LL);
  if (total > std::numeric_limits<int>::max())
    throw Shared<RunError>(fmt::format(
        "{} of {:.2f} GB would be gathered in one MPI message, which carries at most {:.2f} GB "
        "(a distributed run gathers its points to process 0 for the histories and checkpoints): "
        "run it on fewer "
        "points, or on one process",
        what, total / 1e9, std::numeric_limits<int>::max() / 1e9));
  return {sizes.begin(), sizes.end()};
}

std::vector<int> displacements(const std::vector<int>& counts) {
  std::vector<int> at(counts.size(), 0);
  std::exclusive_scan(counts.begin(), counts.end(), at.begin(), 0);
  return at;
}

class MpiCommunicator final : public Communicator {
 public:
  MpiCommunicator() : comm_(PETSC_COMM_WORLD) {
    MPI_Comm_rank(comm_, &rank_);
    MPI_Comm_size(comm_, &size_);
  }
  int rank() const override { return rank_; }
  int size() const override { return size_; }

  // Reduced on process 0 and broadcast, so that every process has the same bits (an all-reduce
  // may add in a different order on each).
  void sum(double* values, std::size_t count) const override {
    if (count == 0) return;
    std::vector<double> total(rank_ == 0 ? count : 0);
    check(MPI_Reduce(values, rank_ == 0 ? total.data() : nullptr, static_cast<int>(count),
                     MPI_DOUBLE, MPI_SUM, 0, comm_),
          "MPI_Reduce");
    if (rank_ == 0) std::copy(total.begin(), total.end(), values);
    check(MPI_Bcast(values, static_cast<int>(count), MPI_DOUBLE, 0, comm_), "MPI_Bcast");
  }
  void max(int* values, std::size_t count) const override {
    if (count == 0) return;
    check(MPI_Allreduce(MPI_IN_PLACE, values, static_cast<int>(count), MPI_INT, MPI_MAX, comm_),
          "MPI_Allreduce");
  }
  void max(double* values, std::size_t count) const override {
    if (count == 0) return;  // a maximum is the same bits in any order
    check(MPI_Allreduce(MPI_IN_PLACE, values, static_cast<int>(count), MPI_DOUBLE, MPI_MAX, comm_),
          "MPI_Allreduce");
  }
  bool all(bool value) const override {
    int v = value ? 1 : 0;
    check(MPI_Allreduce(MPI_IN_PLACE, &v, 1, MPI_INT, MPI_MIN, comm_), "MPI_Allreduce");
    return v != 0;
  }
  std::vector<std::string> exchange(const std::vector<std::string>& outgoing) const override {
    std::vector<int> send_counts(size_), receive_counts(size_);
    std::string send;
    for (int r = 0; r < size_; ++r) {
      send_counts[r] = static_cast<int>(outgoing[r].size());
      send += outgoing[r];
    }
    check(MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm_),
          "MPI_Alltoall");
    const std::vector<int> send_at = displacements(send_counts);
    const std::vector<int> receive_at = displacements(receive_counts);
    std::string receive(static_cast<std::size_t>(receive_at.back() + receive_counts.back()), '\0');
    check(MPI_Alltoallv(send.data(), send_counts.data(), send_at.data(), MPI_CHAR, receive.data(),
                        receive_counts.data(), receive_at.data(), MPI_CHAR, comm_),
          "MPI_Alltoallv");
    return split(receive, receive_counts, receive_at);
  }
  std::vector<std::string> all_gather(const std::string& mine) const override {
    const std::vector<int> counts = message_counts(comm_, size_, mine.size(), "data");
    const int count = counts[static_cast<std::size_t>(rank_)];
    const std::vector<int> at = displacements(counts);
    std::string all(static_cast<std::size_t>(at.back() + counts.back()), '\0');
    check(MPI_Allgatherv(mine.data(), count, MPI_CHAR, all.data(), counts.data(), at.data(),
                         MPI_CHAR, comm_),
          "MPI_Allgatherv");
    return split(all, counts, at);
  }
  std::vector<std::string> gather(const std::string& mine) const override {
    const std::vector<int> counts = message_counts(comm_, size_, mine.size(), "output");
    const int count = counts[static_cast<std::size_t>(rank_)];
    const std::vector<int> at = displacements(counts);
    std::string all(rank_ == 0 ? static_cast<std::size_t>(at.back() + counts.back()) : 0, '\0');
    check(MPI_Gatherv(mine.data(), count, MPI_CHAR, all.data(), counts.data(), at.data(), MPI_CHAR,
                      0, comm_),
          "MPI_Gatherv");
    if (rank_ != 0) return {};
    return split(all, counts, at);
  }
  void barrier() const override { check(MPI_Barrier(comm_), "MPI_Barrier"); }
  [[noreturn]] void abort(int code) const override {
    MPI_Abort(comm_, code);
    std::_Exit(code);  // MPI_Abort does not return; should it, this process still ends
  }

 private:
  static std::vector<std::string> split(const std::string& all, const std::vector<int>& counts,
                                        const std::vector<int>& at) {
    std::vector<std::string> parts(counts.size());
    for (std::size_t r = 0; r < counts.size(); ++r) parts[r] = all.substr(at[r], counts[r]);
    return parts;
  }

  MPI_Comm comm_;
  int rank_ = 0, size_ = 1;
};

}  // namespace

std::unique_ptr<Communicator> mpi_world_communicator(const std::string& petsc_options) {
  petsc::initialise(petsc_options);
  return std::make_unique<MpiCommunicator>();
}

}  // namespace geompm
