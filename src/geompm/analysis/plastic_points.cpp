#include "geompm/analysis/plastic_points.hpp"

#include <algorithm>
#include <limits>
#include <string>
#include <unordered_map>

#include "geompm/analysis/output_fields.hpp"
#include "geompm/core/byte_archive.hpp"

namespace geompm {

namespace {

std::vector<std::pair<Index, double>> by_id(const std::vector<Index>& ids,
                                            const std::vector<double>& strain) {
  std::vector<std::pair<Index, double>> pairs(ids.size());
  for (std::size_t i = 0; i < ids.size(); ++i) pairs[i] = {ids[i], strain[i]};
  std::sort(pairs.begin(), pairs.end());
  return pairs;
}

}  // namespace

PlasticPoints::PlasticPoints(const Model& model)
    : start_(by_id(model.points.id, equivalent_plastic_strain(model))) {}

const double* PlasticPoints::start_of(Index id) const {
  const auto it =
      std::lower_bound(start_.begin(), start_.end(),
                       std::pair<Index, double>(id, -std::numeric_limits<double>::infinity()));
  return it != start_.end() && it->first == id ? &it->second : nullptr;
}

void PlasticPoints::update(const Model& model, const Communicator& processes) {
  const std::vector<double> now = equivalent_plastic_strain(model);
  const std::vector<Index>& id = model.points.id;
  flags_.assign(now.size(), 0);
  std::vector<Index> unknown;  // points this process did not hold at the step's start
  std::vector<std::size_t> unknown_at;
  for (std::size_t i = 0; i < now.size(); ++i)
    if (const double* start = start_of(id[i])) {
      flags_[i] = now[i] > *start;
    } else {
      unknown.push_back(id[i]);
      unknown_at.push_back(i);
    }
  if (processes.distributed()) {
    const std::vector<double> start = ask_others(unknown, processes);
    for (std::size_t k = 0; k < unknown_at.size(); ++k)
      flags_[unknown_at[k]] = now[unknown_at[k]] > start[k];
  }
  start_ = by_id(id, now);
}

// Every process says which ids it needs (one all-gather of the few points that crossed a cut in
// the step), and each answers those it held (one exchange).
std::vector<double> PlasticPoints::ask_others(const std::vector<Index>& ids,
                                              const Communicator& processes) const {
  ByteWriter request;
  request.put(ids);
  const std::vector<std::string> requests = processes.all_gather(request.take());
  std::vector<std::string> answers(requests.size());
  for (std::size_t r = 0; r < requests.size(); ++r) {
    if (static_cast<int>(r) == processes.rank()) continue;
    ByteReader in(requests[r], "plastic strains another process asks for");
    std::vector<std::pair<Index, double>> known;
    for (const Index id : in.get<std::vector<Index>>())
      if (const double* start = start_of(id)) known.emplace_back(id, *start);
    ByteWriter out;
    out.put(known);
    answers[r] = out.take();
  }
  std::unordered_map<Index, double> found;
  const std::vector<std::string> replies = processes.exchange(answers);
  for (std::size_t r = 0; r < replies.size(); ++r) {
    if (static_cast<int>(r) == processes.rank()) continue;
    ByteReader in(replies[r], "plastic strains from another process");
    for (const auto& [id, strain] : in.get<std::vector<std::pair<Index, double>>>())
      found.emplace(id, strain);
  }
  // A point no process held (none in a run that only loses points) counts as not plastic.
  std::vector<double> start(ids.size(), std::numeric_limits<double>::infinity());
  for (std::size_t k = 0; k < ids.size(); ++k)
    if (const auto it = found.find(ids[k]); it != found.end()) start[k] = it->second;
  return start;
}

}  // namespace geompm
