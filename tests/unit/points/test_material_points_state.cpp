// The point store saved and loaded (a checkpoint's "points" section): every array comes back bit
// for bit, in the points' order, and a section whose arrays disagree in length is refused.
#include <gtest/gtest.h>

#include <cstring>
#include <string>

#include "geompm/core/byte_archive.hpp"
#include "geompm/core/error.hpp"
#include "geompm/points/material_points.hpp"

namespace geompm {
namespace {

// Points whose every field holds a value of its own (no field left at its default).
MaterialPoints some_points() {
  MaterialPoints p;
  for (int k = 0; k < 5; ++k) {
    const double s = 1.0 / (k + 3.0);
    p.add(k % 2, k % 3, Vec3(s, 2 * s, 0.1 * k), 0.7 * s, 1.9, 10 + k, Vec3(-s, s, 0.0),
          Vec3(0.5 * s, 0.25, 0.0));
    p.sets[k] = 0b101u << k;
    p.displacement[k] = Vec3(1e-300, -s, 3.0);
    p.phase_displacement[k] = Vec3(s, s * s, -s);
    p.velocity[k] = Vec3(2.0, -s, 1e-20);
    p.acceleration[k] = Vec3(-1.0, 0.0, s);
    p.volume[k] *= 1.0 + s;
    p.stress[k] = Mat3::Constant(-s);
    p.deformation_gradient[k](0, 1) = s;
    p.domain_stretch[k] = 1.0 + 0.01 * k;
    p.volume_mismatch[k] = -0.001 * k;
    p.elastic_left_cauchy_green[k](2, 2) = 1.0 + s;
    p.internal[k] = {s, 2 * s, 3 * s, 4 * s};
  }
  p.id[3] = 42;  // ids need not be consecutive once points have left the mesh
  return p;
}

template <class T>
bool same_bytes(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

TEST(MaterialPointsState, LoadsWhatWasSavedBitForBit) {
  const MaterialPoints saved = some_points();
  ByteWriter out;
  saved.save(out);
  MaterialPoints loaded = some_points();
  loaded.add(0, 0, Vec3::Zero(), 1, 1, 0, Vec3::Zero(), Vec3::Zero());  // replaced
  ByteReader in(out.bytes(), "points");
  loaded.load(in);
  ASSERT_EQ(loaded.size(), saved.size());
  EXPECT_TRUE(same_bytes(loaded.id, saved.id));
  EXPECT_TRUE(same_bytes(loaded.body, saved.body));
  EXPECT_TRUE(same_bytes(loaded.material, saved.material));
  EXPECT_TRUE(same_bytes(loaded.sets, saved.sets));
  EXPECT_TRUE(same_bytes(loaded.position, saved.position));
  EXPECT_TRUE(same_bytes(loaded.initial_position, saved.initial_position));
  EXPECT_TRUE(same_bytes(loaded.displacement, saved.displacement));
  EXPECT_TRUE(same_bytes(loaded.phase_displacement, saved.phase_displacement));
  EXPECT_TRUE(same_bytes(loaded.velocity, saved.velocity));
  EXPECT_TRUE(same_bytes(loaded.acceleration, saved.acceleration));
  EXPECT_TRUE(same_bytes(loaded.mass, saved.mass));
  EXPECT_TRUE(same_bytes(loaded.volume, saved.volume));
  EXPECT_TRUE(same_bytes(loaded.initial_volume, saved.initial_volume));
  EXPECT_TRUE(same_bytes(loaded.initial_half_size, saved.initial_half_size));
  EXPECT_TRUE(same_bytes(loaded.stress, saved.stress));
  EXPECT_TRUE(same_bytes(loaded.deformation_gradient, saved.deformation_gradient));
  EXPECT_TRUE(same_bytes(loaded.domain_stretch, saved.domain_stretch));
  EXPECT_TRUE(same_bytes(loaded.volume_mismatch, saved.volume_mismatch));
  EXPECT_TRUE(same_bytes(loaded.elastic_left_cauchy_green, saved.elastic_left_cauchy_green));
  EXPECT_TRUE(same_bytes(loaded.internal, saved.internal));
  EXPECT_TRUE(same_bytes(loaded.cell, saved.cell));
  EXPECT_TRUE(same_bytes(loaded.local, saved.local));
  // Nothing but the 22 fields is written: their bytes (bytes_per_point counts them by capacity;
  // a copy holds no spare capacity) and one count each.
  const MaterialPoints compact = saved;
  EXPECT_DOUBLE_EQ(static_cast<double>(out.bytes().size()),
                   compact.bytes_per_point() * compact.size() + 22 * sizeof(std::uint64_t));
}

TEST(MaterialPointsState, RefusesArraysOfDifferentLengths) {
  MaterialPoints bad = some_points();
  bad.mass.pop_back();
  ByteWriter out;
  bad.save(out);
  MaterialPoints loaded;
  ByteReader in(out.bytes(), "checkpoint.bin: section 'points'");
  try {
    loaded.load(in);
    FAIL() << "accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("checkpoint.bin: section 'points': 5 points, but an "
                                         "array of 4 values"),
              std::string::npos)
        << e.what();
  }
}

}  // namespace
}  // namespace geompm
