// The closed form of the layer tests (tests/unit/analysis: FEM regions, mixed meshes in 2D and
// 3D): an elastic layer of the Hencky material (E = 10000, nu = 0.3) compressed under lateral
// confinement, and the patch test of such a layer compressed by 1 % in one step.
#pragma once

#include <gtest/gtest.h>

#include <cmath>

#include "run_model.hpp"

namespace geompm::testing {

/// The Hencky material's confined compression to the stretch l: sigma = M ln(l) / l (Cauchy, on
/// the current area), M = E (1 - nu) / ((1 + nu) (1 - 2 nu)): the oedometer example's closed form.
inline double hencky_confined_stress(double l, double E = 10000, double nu = 0.3) {
  return E * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) * std::log(l) / l;
}

/// One step of 1 % along the axis `vertical` (y in 2D, z in 3D) of a layer whose top has the
/// area `top_area`: no point leaves its cell, so the points integrate the cells' forces exactly
/// and the homogeneous field is the discrete solution (up to Newton's tolerance): the reactions
/// "top_reaction" and "base_reaction", one stress at every point (no shear on the vertical) and
/// u = (l - 1) x_vertical of the start position.
inline void expect_confined_patch_passes(const ModelRun& run, const MaterialPoints& points,
                                         int vertical, double top_area = 1.0) {
  const double l = 0.99, expected = hencky_confined_stress(l),
               tolerance = 1e-8 * std::abs(expected);
  ASSERT_EQ(run.column("top_reaction").size(), 2u);
  EXPECT_NEAR(run.column("top_reaction")[1], top_area * expected, top_area * tolerance);
  EXPECT_NEAR(run.column("base_reaction")[1], -top_area * expected, top_area * tolerance);
  ASSERT_GT(points.size(), 0);
  for (Index p = 0; p < points.size(); ++p) {
    EXPECT_NEAR(points.stress[p](vertical, vertical), expected, tolerance) << "point " << p;
    const Vec3 start = points.position[p] - points.displacement[p];
    for (int i = 0; i < vertical; ++i) {
      EXPECT_NEAR(points.stress[p](i, vertical), 0.0, tolerance) << "point " << p;
      EXPECT_NEAR(points.displacement[p](i), 0.0, 1e-10) << "point " << p;
    }
    EXPECT_NEAR(points.displacement[p](vertical), (l - 1.0) * start(vertical), 1e-10)
        << "point " << p;
  }
}

/// Ten steps of 1 % to 10 %: an all-FEM layer's deformation is homogeneous, so its top reaction
/// is the closed form (times `top_area`) at every step, to Newton's tolerance.
inline void expect_top_reaction_as_closed_form(const ModelRun& run, double top_area = 1.0) {
  const std::vector<double> top = run.column("top_reaction");
  ASSERT_EQ(top.size(), 11u);
  for (std::size_t k = 1; k < top.size(); ++k) {
    const double expected = top_area * hencky_confined_stress(1.0 - 0.01 * static_cast<double>(k));
    EXPECT_NEAR(top[k], expected, 1e-8 * std::abs(expected)) << "step " << k;
  }
}

}  // namespace geompm::testing
