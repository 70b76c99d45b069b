// The material point store: a structure of arrays, one array per field, so that each loop of
// the three-phase step streams only the fields it needs. Points carry the whole state of the
// continuum between steps (the grid is reset after every step, seed paper §2).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>
#include <vector>

#include "geompm/core/types.hpp"
#include "geompm/materials/internal_variables.hpp"

namespace geompm {

class ByteWriter;
class ByteReader;

struct MaterialPoints {
  std::vector<Index> id;            // stable id, reported when a point leaves the mesh
  std::vector<Index> body;          // index into the model's bodies
  std::vector<Index> material;      // index into the model's materials
  std::vector<std::uint64_t> sets;  // bit k set: the point belongs to point set k
  std::vector<Vec3> position;
  std::vector<Vec3> initial_position;
  std::vector<Vec3> displacement;        // total, since the point was seeded
  std::vector<Vec3> phase_displacement;  // since the start of the current analysis phase
  std::vector<Vec3> velocity;
  std::vector<Vec3> acceleration;
  std::vector<double> mass;
  std::vector<double> volume;  // current; per radian in axisymmetry
  std::vector<double> initial_volume;
  std::vector<Vec3> initial_half_size;  // the seeded domain's half-lengths (SeedPoint::half_size)
  std::vector<Mat3> stress;             // Cauchy, tension positive
  std::vector<Mat3> deformation_gradient;  // total F (the averaged F^ of a mixed point, §12)
  /// How much a mixed point's own volume change, along the grid's directions, has exceeded its
  /// cell's average over all steps so far, as a stretch: its domain follows the grid's motion,
  /// F_domain = F^ scaled by this on the grid's directions (docs/theory.md eq. 12.7); 1 without
  /// an average.
  std::vector<double> domain_stretch;
  /// A mixed point evaluated at the field's pressure (docs/theory.md §14): how far the log of its
  /// kinematic volume ratio has run ahead of its material's over all steps so far, ln J_k - ln R
  /// (eq. 14.2 ties its mean over each node's support to the stabilisation); 0 otherwise.
  std::vector<double> volume_mismatch;
  std::vector<Mat3> elastic_left_cauchy_green;  // b_e = F_e F_e^T
  std::vector<InternalVariables> internal;
  std::vector<Index> cell;  // cell containing the point
  std::vector<Vec3> local;  // reference coordinates in that cell

  Index size() const { return static_cast<Index>(id.size()); }

  /// Appends one point with zero velocity, zero stress and F = b_e = I; `half_size`: the region
  /// the point represents, as seeding found it (SeedPoint).
  Index add(Index body_index, Index material_index, const Vec3& x, double volume, double density,
            Index cell, const Vec3& xi, const Vec3& half_size);

  /// The deformation gradient of point p's domain: F scaled by its domain stretch on the first
  /// `dim` directions (the grid's).
  Mat3 domain_deformation(Index p, int dim) const {
    Mat3 F = deformation_gradient[p];
    F.topRows(dim) *= domain_stretch[p];
    return F;
  }

  /// Removes the points whose flag is set, keeping the order of the rest.
  void remove(const std::vector<char>& flag);

  /// The points `which` (indices, in that order) as a store of their own.
  MaterialPoints subset(const std::vector<Index>& which) const;
  /// Appends every point of `more` after these.
  void append(const MaterialPoints& more);

  /// Sorts the points by cell (stable), so that a cell's points are contiguous in memory.
  void sort_by_cell();

  /// Writes every array (a checkpoint's "points" section), bit for bit, in the points' order.
  void save(ByteWriter& out) const;
  /// Replaces every array by what save() wrote; throws InputError if the arrays' lengths differ.
  void load(ByteReader& in);

  /// The arrays as save() writes them: each a count, then that many values of a fixed size.
  struct SavedLayout {
    std::vector<std::size_t> value_bytes;  // per array, in save()'s order
    std::size_t cell_array = 0;            // which of them is `cell`
  };
  static SavedLayout saved_layout();
  /// Appends to array `array` (save()'s order) the values of `bytes`, whole values as save()
  /// wrote them, of points first, first + 1, ...: those whose `keep` flag is set. A reader that
  /// keeps some points only fills every array so (points/saved_points.hpp).
  void append_saved(std::size_t array, std::string_view bytes, const std::vector<char>& keep,
                    std::size_t first);
  /// Writes of array `array` (save()'s order) the values of the points which[0], ...,
  /// which[count - 1], as save() writes them (no count): a writer that passes the points on a
  /// slice at a time writes every array so (points/streamed_points.hpp).
  void put_saved(std::size_t array, const Index* which, std::size_t count, ByteWriter& out) const;

  /// Bytes held per point by the arrays (capacity included), for docs/performance.md.
  double bytes_per_point() const;
};

}  // namespace geompm
