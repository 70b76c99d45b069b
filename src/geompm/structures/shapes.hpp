// The built-in structure shapes (docs/user-guide.md, "structures"), meshed with the Gmsh API from
// a few dimensions: a pipe (a disc or ring; a sphere or spherical shell in axisymmetry; a
// horizontal cylinder along y in 3D), a T-bar (a solid bar, as the pipe), a spudcan (a lower cone
// of the given tip angle, a vertical shoulder, an upper cone up to the shaft, the shaft), a plate
// or sheet pile (with a pointed tip; a pile with a conical tip in axisymmetry), a cone
// penetrometer with its shaft, and a flat footing. The profiled shapes are bodies of revolution
// about the vertical axis through `position`: plane strain meshes their full section,
// axisymmetry their half-section at x >= 0 (the axis at x = 0), 3D the body itself (revolved;
// the plate and the footing extruded along y instead).
#pragma once

#include <vector>

#include "geompm/mesh/mesh.hpp"
#include "geompm/spec/model_spec.hpp"

namespace geompm {

/// The shape's half-section at x >= 0 about its axis, from the axis at the bottom (its tip or
/// the centre of its base) outwards and up to the axis at the top, with the anchor at the
/// origin: a polygon for the profiled shapes (spudcan, plate, cone, footing).
std::vector<Vec3> shape_profile(const spec::StructureShape& shape);

/// The shape's mesh for the kinematics, placed at shape.position. Throws std::invalid_argument
/// naming the dimension that is missing or out of range, or a shape the kinematics does not
/// allow (a T-bar in axisymmetry, a shape off the axis in axisymmetry); std::runtime_error if
/// Gmsh fails.
Mesh shape_mesh(const spec::StructureShape& shape, Kinematics kinematics);

}  // namespace geompm
