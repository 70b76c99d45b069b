// PointIntegrator's cell kernels for quadrilaterals (quad4), in a translation unit of their own
// (docs/performance.md, build times).
#include "geompm/physics/point_integrator_cells.hpp"

namespace geompm {

GEOMPM_POINT_INTEGRATOR_CELLS(Quad4)

}  // namespace geompm
