// PointIntegrator's cell kernels for triangles (tri3, tri6), in a translation unit of their own
// (docs/performance.md, build times).
#include "geompm/physics/point_integrator_cells.hpp"

namespace geompm {

GEOMPM_POINT_INTEGRATOR_CELLS(Tri3)
GEOMPM_POINT_INTEGRATOR_CELLS(Tri6)

}  // namespace geompm
