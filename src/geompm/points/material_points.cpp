#include "geompm/points/material_points.hpp"

#include <fmt/format.h>

#include <numeric>

#include "geompm/core/byte_archive.hpp"
#include "geompm/core/error.hpp"

namespace geompm {

Index MaterialPoints::add(Index body_index, Index material_index, const Vec3& x, double vol,
                          double density, Index cell_index, const Vec3& xi, const Vec3& half_size) {
  const Index next_id = id.empty() ? 0 : id.back() + 1;
  id.push_back(next_id);
  body.push_back(body_index);
  material.push_back(material_index);
  sets.push_back(0);
  position.push_back(x);
  initial_position.push_back(x);
  displacement.push_back(Vec3::Zero());
  phase_displacement.push_back(Vec3::Zero());
  velocity.push_back(Vec3::Zero());
  acceleration.push_back(Vec3::Zero());
  mass.push_back(vol * density);
  volume.push_back(vol);
  initial_volume.push_back(vol);
  initial_half_size.push_back(half_size);
  stress.push_back(Mat3::Zero());
  deformation_gradient.push_back(Mat3::Identity());
  domain_stretch.push_back(1.0);
  volume_mismatch.push_back(0.0);
  elastic_left_cauchy_green.push_back(Mat3::Identity());
  internal.push_back(InternalVariables{});
  cell.push_back(cell_index);
  local.push_back(xi);
  return size() - 1;
}

namespace {

// Applies the same reordering (or filtering) to every field, so no field is ever forgotten.
// With several stores, fn gets the same field of each (copying between stores).
template <class Fn, class... Stores>
void for_each_field_of(Fn&& fn, Stores&... p) {
  fn(p.id...);
  fn(p.body...);
  fn(p.material...);
  fn(p.sets...);
  fn(p.position...);
  fn(p.initial_position...);
  fn(p.displacement...);
  fn(p.phase_displacement...);
  fn(p.velocity...);
  fn(p.acceleration...);
  fn(p.mass...);
  fn(p.volume...);
  fn(p.initial_volume...);
  fn(p.initial_half_size...);
  fn(p.stress...);
  fn(p.deformation_gradient...);
  fn(p.domain_stretch...);
  fn(p.volume_mismatch...);
  fn(p.elastic_left_cauchy_green...);
  fn(p.internal...);
  fn(p.cell...);
  fn(p.local...);
}

template <class Fn>
void for_each_field(MaterialPoints& p, Fn&& fn) {
  for_each_field_of(fn, p);
}

}  // namespace

void MaterialPoints::remove(const std::vector<char>& flag) {
  for_each_field(*this, [&](auto& field) {
    std::size_t out = 0;
    for (std::size_t i = 0; i < field.size(); ++i)
      if (!flag[i]) field[out++] = field[i];
    field.resize(out);
  });
}

void MaterialPoints::sort_by_cell() {
  std::vector<Index> order(cell.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](Index a, Index b) { return cell[a] < cell[b]; });
  bool sorted = true;
  for (std::size_t i = 0; i < order.size(); ++i) sorted = sorted && order[i] == Index(i);
  if (sorted) return;
  for_each_field(*this, [&](auto& field) {
    auto copy = field;
    for (std::size_t i = 0; i < order.size(); ++i) field[i] = copy[order[i]];
  });
}

// Through for_each_field, so that a field added to the store is saved without another edit.
void MaterialPoints::save(ByteWriter& out) const {
  for_each_field(const_cast<MaterialPoints&>(*this), [&](const auto& field) { out.put(field); });
}

void MaterialPoints::load(ByteReader& in) {
  for_each_field(*this, [&](auto& field) { in.get(field); });
  in.expect_end();
  for_each_field(*this, [&](const auto& field) {
    if (field.size() != id.size())
      throw InputError(fmt::format("{}: {} points, but an array of {} values", in.context(),
                                   id.size(), field.size()));
  });
}

MaterialPoints MaterialPoints::subset(const std::vector<Index>& which) const {
  MaterialPoints out;
  for_each_field_of(
      [&](auto& to, const auto& from) {
        to.reserve(which.size());
        for (Index p : which) to.push_back(from[p]);
      },
      out, *this);
  return out;
}

void MaterialPoints::append(const MaterialPoints& more) {
  for_each_field_of(
      [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); }, *this,
      more);
}

MaterialPoints::SavedLayout MaterialPoints::saved_layout() {
  SavedLayout layout;
  MaterialPoints none;
  for_each_field(none, [&](const auto& field) {
    using T = typename std::decay_t<decltype(field)>::value_type;
    if (static_cast<const void*>(&field) == static_cast<const void*>(&none.cell))
      layout.cell_array = layout.value_bytes.size();
    layout.value_bytes.push_back(archived_bytes<T>());
  });
  return layout;
}

void MaterialPoints::append_saved(std::size_t array, std::string_view bytes,
                                  const std::vector<char>& keep, std::size_t first) {
  std::size_t k = 0;
  for_each_field(*this, [&](auto& field) {
    if (k++ != array) return;
    using T = typename std::decay_t<decltype(field)>::value_type;
    ByteReader in(bytes, "saved points");
    for (std::size_t i = first; in.remaining() > 0; ++i) {
      T value{};
      in.get(value);
      if (keep[i]) field.push_back(value);
    }
  });
}

void MaterialPoints::put_saved(std::size_t array, const Index* which, std::size_t count,
                               ByteWriter& out) const {
  std::size_t k = 0;
  for_each_field(const_cast<MaterialPoints&>(*this), [&](const auto& field) {
    if (k++ != array) return;
    for (std::size_t i = 0; i < count; ++i) out.put(field[which[i]]);
  });
}

double MaterialPoints::bytes_per_point() const {
  if (id.empty()) return 0.0;
  double bytes = 0;
  for_each_field(const_cast<MaterialPoints&>(*this), [&](auto& field) {
    bytes += double(field.capacity()) * sizeof(typename std::decay_t<decltype(field)>::value_type);
  });
  return bytes / double(id.size());
}

}  // namespace geompm
