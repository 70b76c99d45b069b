// PointIntegrator's cell kernels for tetrahedra, hexahedra and pyramids (tet4, hex8, pyramid5),
// in a translation unit of their own (docs/performance.md, build times).
#include "geompm/physics/point_integrator_cells.hpp"

namespace geompm {

GEOMPM_POINT_INTEGRATOR_CELLS(Tet4)
GEOMPM_POINT_INTEGRATOR_CELLS(Hex8)
GEOMPM_POINT_INTEGRATOR_CELLS(Pyramid5)

}  // namespace geompm
