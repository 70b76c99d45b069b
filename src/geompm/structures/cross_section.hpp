// The mean stress over a cross section of a deformable structure (issue 42: the seed's Fig. 3
// plots the mean vertical stress at a pile's top; docs/theory.md eq. 17.15): the line (2D) or
// plane (3D) through a point with a unit normal n cuts the mesh in the current configuration, and
// the mean of n . sigma n over the cut weighs each cell's mean stress by the length (area) of the
// cut through it (times r in axisymmetry, per radian).
#pragma once

#include "geompm/structures/deformable_structure.hpp"

namespace geompm {

struct SectionStress {
  double mean_normal_stress = 0.0;  // (1/A) integral of n . sigma n over the cut
  double measure = 0.0;             // A: the cut's length (2D), area (3D), integral of r ds
};

/// NaN mean and zero measure where the section misses the structure.
SectionStress section_stress(const DeformableStructure& structure, const Vec3& point,
                             const Vec3& normal);

}  // namespace geompm
