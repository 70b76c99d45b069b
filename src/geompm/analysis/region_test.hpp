// Whether a region of the model file (spec::Region: all, a cell group, a box, polygon, circle or
// sphere) holds a position: used to seed bodies, select point sets and, in the K0 procedure, to
// find the soil along a vertical.
#pragma once

#include <optional>
#include <utility>
#include <vector>

#include "geompm/mesh/mesh.hpp"
#include "geompm/spec/model_spec.hpp"

namespace geompm {

class RegionTest {
 public:
  /// Throws InputError (at the region's source) for a group the mesh does not have.
  RegionTest(const spec::Region& region, const Mesh& mesh, int dim);

  /// Whether the region holds position x; a group region asks whether it holds `cell` (the
  /// cell containing x).
  bool contains(const Vec3& x, Index cell) const;
  /// Whether the region is a cell group (then contains() needs the right cell).
  bool needs_cell() const { return cells_ != nullptr; }

  /// Bounding box of a geometric region (nullopt for All and Group).
  std::optional<std::pair<Vec3, Vec3>> bounds() const;

 private:
  bool inside_polygon(const Vec3& x) const;

  spec::Region region_;
  int dim_;
  const std::vector<Index>* cells_ = nullptr;
};

/// "a, b, c" for the names of a mesh's groups, "(none)" if there are none.
std::string group_names(const std::map<std::string, std::vector<Index>>& groups);

}  // namespace geompm
