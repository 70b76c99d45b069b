// Support for the model reader tests of tests/unit/io/: a valid model (a column under
// self-weight, then loaded at the top) that the tests edit, and where a marker stands in a text.
//
// Header-only (every function and variable `inline`): all the .cpp files of this directory are
// linked into one test executable.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <string>
#include <vector>

namespace geompm::testing {

// The valid model every case starts from, by section so that a case can replace a whole one.
inline const std::string kHeader =
    R"m(# A column under self-weight, then loaded at the top (kN, m, s, t).
title: Column under self-weight
analysis:
  kinematics: plane_strain
)m";
inline const std::string kMesh = R"m(mesh:
  generate:
    cell: quad4
    origin: [0, 0]
    x: {length: 1, cells: 1}
    y:
      - {length: 40, cells: 16}
      - {length: 20, cells: 8, ratio: 2}
)m";
inline const std::string kMaterials = R"m(materials:
  soil:
    model: linear_elastic
    E: 1000
    nu: 0.0
    density: 0.08
)m";
inline const std::string kBodies = R"m(bodies:
  column:
    material: soil
    region: {box: {min: [0, 0], max: [1, 50]}}
    points_per_cell: 4
    initial_velocity: ["0.1*sin(pi*y/50)", "0"]
  block:
    material: soil
    region:
      polygon: [[0, 50], [1, 50], [0.5, 55]]
    points_per_cell: 9
point_sets:
  top:
    body: column
    region: {box: {min: [0, 49], max: [1, 50]}}
  side:
    region: {circle: {center: [0.5, 25], radius: 0.5}}
)m";
inline const std::string kPhases = R"m(phases:
  - name: gravity
    duration: 1.0
    time_step: {initial: 0.1, min: 1.0e-4, max: 0.2, growth: 1.5, cutback: 0.5, target_iterations: 4}
    dynamics: quasi_static
    newton: {max_iterations: 15, residual_tolerance: 1.0e-8, displacement_tolerance: 1.0e-8}
    gravity: {acceleration: [0, -10], ramp: true}
    fixities:
      - {boundary: left, fix: normal}
      - {plane: {axis: x, value: 1.0}, fix: normal}
      - {boundary: bottom, fix: all}
  - name: loading
    duration: 2
    time_step: 0.05
    dynamics: {newmark: {beta: 0.3, gamma: 0.6}}
    gravity: {acceleration: [0, -10]}
    fixities:
      - {boundary: bottom, fix: [x, y]}
    prescribed_motion:
      - {point_set: top, displacement: [~, "-0.1*t"]}
    loads:
      - {point_set: side, force: ["0", "-10*t"]}
)m";
inline const std::string kOutput = R"m(output:
  vtk: {every: 2, grid: false}
  history:
    - {quantity: displacement, point_set: top, component: y, name: top_uy}
    - {quantity: reaction, boundary: bottom, component: y}
    - {quantity: kinetic_energy}
  plots:
    - {file: settlement.png, x: top_uy, y: [reaction_bottom_y], title: Settlement, y_scale: -1}
numerics: {empty_cell_stiffness: 1.0e-5, buffer_layers: 2, lost_points: remove, linear_solver: sparse_lu}
)m";
inline const std::string kValidModel = kHeader + kMesh + kMaterials + kBodies + kPhases + kOutput;

/// Replaces the one occurrence of `from` by `to`.
struct Edit {
  std::string from, to;
};

/// How often `part` stands in `text` (overlapping occurrences count).

inline std::size_t occurrences(const std::string& text, const std::string& part) {
  std::size_t count = 0;
  for (std::size_t at = text.find(part); at != std::string::npos; at = text.find(part, at + 1))
    ++count;
  return count;
}

/// `text` with the edits applied in turn; each `from` must occur exactly once (a test failure
/// if not).
inline std::string apply(std::string text, const std::vector<Edit>& edits) {
  for (const Edit& edit : edits) {
    EXPECT_EQ(occurrences(text, edit.from), 1u) << "edit source not unique: " << edit.from;
    const std::size_t at = text.find(edit.from);
    if (at != std::string::npos) text.replace(at, edit.from.size(), edit.to);
  }
  return text;
}

/// 1-based line where `marker` starts in `text`; the marker must occur exactly once (a test
/// failure if not).
inline int line_of(const std::string& text, const std::string& marker) {
  EXPECT_EQ(occurrences(text, marker), 1u) << "line marker not unique: " << marker;
  const std::size_t at = text.find(marker);
  return 1 +
         static_cast<int>(std::count(text.begin(), text.begin() + std::min(at, text.size()), '\n'));
}

}  // namespace geompm::testing
