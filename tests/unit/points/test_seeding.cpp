// Seeding records each point's domain: on quadrilaterals and hexahedra the half-lengths of its
// sub-cell along the axes, the initial particle domain of GIMP (docs/theory.md eq. 9.4), which
// tile an axis-aligned cell exactly.
#include "geompm/points/seeding.hpp"

#include <gtest/gtest.h>

#include "geompm/mesh/structured_mesh.hpp"

#include <map>

namespace geompm {
namespace {

TEST(Seeding, HalfSizesTileAnAxisAlignedCell) {
  for (CellType type : {CellType::Quad4, CellType::Hex8}) {
    StructuredMeshSpec spec;
    spec.cell_type = type;
    spec.axes = {std::vector<AxisSegment>{{2.0, 1, 1.0}}, {{1.0, 1, 1.0}}, {{0.5, 1, 1.0}}};
    const Mesh mesh = generate_structured_mesh(spec);
    const int dim = mesh.dim();
    for (int k : {1, 2, 3}) {
      const int count = dim == 2 ? k * k : k * k * k;
      const auto points = seed_cell(mesh, 0, count, false);
      double covered = 0.0;
      for (const auto& p : points) {
        double box = 1.0;
        for (int d = 0; d < dim; ++d) {
          const double extent = d == 0 ? 2.0 : d == 1 ? 1.0 : 0.5;
          EXPECT_NEAR(p.half_size(d), 0.5 * extent / k, 1e-14);
          box *= 2 * p.half_size(d);
        }
        EXPECT_NEAR(box, p.volume, 1e-14);
        covered += box;
      }
      EXPECT_NEAR(covered, dim == 2 ? 2.0 : 1.0, 1e-13);
    }
  }
}

}  // namespace
}  // namespace geompm
