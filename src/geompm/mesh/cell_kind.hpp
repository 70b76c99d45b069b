// What a cell of the background mesh is for (seed §3.4, docs/theory.md §19): MPM cells hold
// material points and are reset (or relaxed) after every step; FEM cells are ordinary
// updated-Lagrangian finite elements integrated at their Gauss points, their nodes moving with
// the solution; buffer cells are MPM cells seeded with no points, which catch points moving out
// of the body (e.g. above the surface).
#pragma once

#include <string>

namespace geompm {

enum class CellKind : unsigned char { Mpm, Fem, Buffer };

inline const char* to_string(CellKind kind) {
  switch (kind) {
    case CellKind::Fem:
      return "fem";
    case CellKind::Buffer:
      return "buffer";
    case CellKind::Mpm:
      break;
  }
  return "mpm";
}

}  // namespace geompm
