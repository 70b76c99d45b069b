// The K0 procedure (docs/theory.md §10): the analysis starts from the geostatic stresses of level
// ground in horizontal layers, sigma_v = -(weight of the soil above, per unit area) and
// sigma_h = K0 sigma_v, stored in the points as the elastic strain that gives them.
#pragma once

#include <string>
#include <vector>

#include "geompm/analysis/model.hpp"

namespace geompm {

/// The soil along one vertical, bottom up: where each layer (a material) is.
struct SoilProfile {
  struct Segment {
    double bottom = 0.0, top = 0.0;
    Index material = -1;  // index into the model's materials; -1: no soil of the procedure
  };
  std::vector<Segment> segments;
  Vec3 through = Vec3::Zero();  // a position on the vertical
  double surface = 0.0;         // top of the highest soil segment

  /// Weight per unit area of the soil between `elevation` and the surface, divided by |g|:
  /// the integral of the density (eq. 9.1 without g).
  double mass_above(double elevation, const std::vector<double>& densities) const;
  /// The segment holding `elevation` (nullptr above or below the profile).
  const Segment* at(double elevation) const;
};

/// Sets the geostatic stress of the K0 procedure of the model's first phase (if it has one) in
/// the points of its bodies. Called by build_model once the points are seeded. Throws
/// InputError, at the procedure's key path, when the ground is not level in horizontal layers
/// (a point above the surface found on the reference vertical, a point whose material is not the
/// one found at its elevation on that vertical, soil that does not reach the surface above a
/// point, a gap in the soil), when a material cannot start from a stress, or when a point's
/// stress lies outside its material's yield surface. In a distributed run, pass its processes
/// (collective): the reference vertical is found from every process's points, and every process
/// throws the error one met.
void apply_k0_procedure(Model& model, const Communicator& processes = serial_communicator());

/// The profile of the procedure's bodies along the vertical through `through` (built by
/// sampling and bisection; exact to round-off at the interfaces of boxes, polygons, layers and
/// cell groups).
SoilProfile soil_profile(const Model& model, const std::vector<Index>& bodies, const Vec3& through);

}  // namespace geompm
