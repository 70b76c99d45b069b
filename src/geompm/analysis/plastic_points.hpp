// Which material points flowed plastically in the last step: the `plastic` flag of the points'
// ParaView files. A point did if its equivalent plastic strain grew in the step. The strains at
// the step's start are kept by the points' ids, since the points are reordered by cell every
// step and lost ones removed; in a distributed run a point that crossed into another process's
// cell in the step finds its start strain on the process it came from.
#pragma once

#include <utility>
#include <vector>

#include "geompm/analysis/model.hpp"
#include "geompm/core/communicator.hpp"

namespace geompm {

class PlasticPoints {
 public:
  /// The strains of the points `model` holds now, as the next step's start.
  explicit PlasticPoints(const Model& model);

  /// After a converged step: per point this process holds (its order now), 1 if its equivalent
  /// plastic strain grew since the last call, 0 if not or if no process knew its start. Then
  /// keeps the strains now as the next step's start. Collective in a distributed run.
  void update(const Model& model, const Communicator& processes);

  /// The flags update() found, per point of the model as it was then.
  const std::vector<Index>& flags() const { return flags_; }

 private:
  /// The start strain of point `id`, or null if this process did not hold it.
  const double* start_of(Index id) const;
  /// The start strains of the points `ids` from the processes that held them (collective).
  std::vector<double> ask_others(const std::vector<Index>& ids,
                                 const Communicator& processes) const;

  std::vector<std::pair<Index, double>> start_;  // (id, strain), ascending by id
  std::vector<Index> flags_;
};

}  // namespace geompm
