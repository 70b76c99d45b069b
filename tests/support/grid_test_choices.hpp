// What the grid's unit tests share: a material choice for every point of an example, the
// parameters of the plastic soils they use, and points moved off their seeding positions.
#pragma once

#include <map>
#include <random>
#include <string>

#include "run_model.hpp"

namespace geompm::testing {

// A material for every point of the example, in the mixed formulation when `mixed`, seeing its
// cell's volume change when `volume_average` (F-bar, theory §12).
struct MaterialChoice {
  std::string model;
  std::map<std::string, double> parameters;
  bool mixed = false;
  bool volume_average = false;
  bool field_pressure = false;        // the material at the field's pressure (theory §14)
  bool incremental_pressure = false;  // the step's change of the pressure equation (eq. 11.8)
};

/// Moves every point by up to `fraction` of its domain half-size along each axis (in the
/// mesh), and relocates it.
inline void scatter_points(Model& model, double fraction) {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  auto& p = model.points;
  for (Index i = 0; i < p.size(); ++i) {
    Vec3 x = p.position[i];
    for (int d = 0; d < model.mesh.dim(); ++d)
      x(d) += fraction * p.initial_half_size[i](d) * u(rng);
    const auto where = model.locator->locate(x, p.cell[i]);
    ASSERT_TRUE(where);
    p.position[i] = x;
    p.cell[i] = where->cell;
    p.local[i] = where->xi;
  }
}

inline const std::map<std::string, double> tresca_parameters{
    {"su", 5.0}, {"E", 1e4}, {"nu", 0.49}, {"density", 1.0}};
inline const std::map<std::string, double> mohr_coulomb_parameters{
    {"c", 2.0}, {"phi", 30.0}, {"psi", 10.0}, {"E", 1e4}, {"nu", 0.3}, {"density", 1.0}};
inline const MaterialChoice mixed_tresca{"tresca", tresca_parameters, true, true};

}  // namespace geompm::testing
