#include "geompm/points/point_exchange.hpp"

#include <algorithm>
#include <numeric>
#include <string>

#include "geompm/core/byte_archive.hpp"

namespace geompm {

namespace {

std::string pack(const MaterialPoints& points) {
  ByteWriter out;
  points.save(out);
  return out.take();
}

MaterialPoints unpack(const std::string& bytes) {
  MaterialPoints points;
  if (bytes.empty()) return points;
  ByteReader in(bytes, "points from another process");
  points.load(in);
  return points;
}

}  // namespace

void keep_own_points(MaterialPoints& points, const std::vector<int>& cell_part, int rank) {
  std::vector<char> other(points.size(), 0);
  for (Index p = 0; p < points.size(); ++p) other[p] = cell_part[points.cell[p]] != rank;
  points.remove(other);
}

Index migrate_points(MaterialPoints& points, const std::vector<int>& cell_part,
                     const Communicator& communicator) {
  const int size = communicator.size(), rank = communicator.rank();
  std::vector<std::vector<Index>> leaving(size);
  std::vector<char> gone(points.size(), 0);
  for (Index p = 0; p < points.size(); ++p)
    if (const int to = cell_part[points.cell[p]]; to != rank) {
      leaving[to].push_back(p);
      gone[p] = 1;
    }
  std::vector<std::string> outgoing(size);
  Index sent = 0;
  for (int r = 0; r < size; ++r)
    if (!leaving[r].empty()) {
      outgoing[r] = pack(points.subset(leaving[r]));
      sent += static_cast<Index>(leaving[r].size());
    }
  const std::vector<std::string> incoming = communicator.exchange(outgoing);
  if (sent > 0) points.remove(gone);
  for (int r = 0; r < size; ++r)
    if (r != rank && !incoming[r].empty()) points.append(unpack(incoming[r]));
  return sent;
}

MaterialPoints gather_points(const MaterialPoints& points, const Communicator& communicator) {
  const std::vector<std::string> parts = communicator.gather(pack(points));
  MaterialPoints all;
  for (const std::string& part : parts) all.append(unpack(part));
  std::vector<Index> order(all.size());
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return all.id[a] < all.id[b]; });
  return all.subset(order);
}

}  // namespace geompm
