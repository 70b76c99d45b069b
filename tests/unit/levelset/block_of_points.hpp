// A block of material points that fills whole cells of a structured mesh exactly: one point at
// each Gauss point of the element's rule (exact for the mass matrix), carrying the Gauss weight
// times det J (times the radius in axisymmetry) as its volume. Sums over the points of N_I, and
// of N_I r, are then the exact integrals over the filled cells, so the level set of such a block
// takes its closed-form values (docs/theory.md eq. 16.1) to round-off.
#pragma once

#include <functional>
#include <memory>
#include <vector>

#include "geompm/materials/linear_elastic.hpp"
#include "geompm/mesh/cell_dispatch.hpp"
#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/mesh_topology.hpp"
#include "geompm/mesh/structured_mesh.hpp"
#include "geompm/physics/grid_system.hpp"

namespace geompm::testing {

/// A mesh, its grid and the points of a block of it, for the level-set tests.
struct Block {
  Mesh mesh;
  MeshTopology topology;
  std::vector<std::unique_ptr<Material>> owned;
  std::vector<const Material*> materials;
  MaterialPoints points;
  std::unique_ptr<GridSystem> grid;
};

/// Cells of `size` (unit by default) along each axis from `origin`; `cells` per axis.
inline StructuredMeshSpec block_mesh(CellType type, std::array<int, 3> cells,
                                     const Vec3& origin = Vec3::Zero(), double size = 1.0) {
  StructuredMeshSpec spec;
  spec.cell_type = type;
  spec.origin = origin;
  for (int i = 0; i < 3; ++i) spec.axes[i] = {AxisSegment{size * cells[i], cells[i], 1.0}};
  return spec;
}

/// Fills every cell with Gauss points of body body_at(centroid) (none if negative; material index
/// = body index, densities 2 and 3 for bodies 0 and 1), then initialises the grid. Cells where
/// `fem_at(centroid)` holds are FEM cells (docs/theory.md §19): no points, full in the grid.
inline std::unique_ptr<Block> fill_block(const StructuredMeshSpec& spec, Kinematics kinematics,
                                         const std::function<int(const Vec3&)>& body_at,
                                         const std::function<bool(const Vec3&)>& fem_at = {}) {
  auto block = std::make_unique<Block>();
  block->mesh = generate_structured_mesh(spec);
  block->topology = build_mesh_topology(block->mesh);
  for (double density : {2.0, 3.0}) {
    block->owned.push_back(std::make_unique<LinearElastic>(1000.0, 0.3, density));
    block->materials.push_back(block->owned.back().get());
  }
  const bool radial = kinematics == Kinematics::Axisymmetric;
  std::vector<char> fem(block->mesh.num_cells(), 0);
  for_each_mesh_cell_typed(block->mesh, [&](auto e, Index c) {
    using E = decltype(e);
    constexpr CellType T = cell_type_of<E>;
    const NodeCoordinates<T> X = cell_node_coordinates<T>(block->mesh, c);
    Vec3 centroid = Vec3::Zero();
    centroid.head<E::dim>() = map_to_physical<T>(X, E::centroid());
    const int body = body_at(centroid);
    fem[c] = fem_at && fem_at(centroid);
    if (body < 0 || fem[c]) return;
    for (int q = 0; q < E::quadrature_size(); ++q) {
      const typename E::Local xi = E::quadrature_point(q);
      Vec3 x = Vec3::Zero(), local = Vec3::Zero();
      x.head<E::dim>() = map_to_physical<T>(X, xi);
      local.head<E::dim>() = xi;
      double volume = E::quadrature_weight(q) * jacobian<T>(X, xi).determinant();
      if (radial) volume *= x(0);
      block->points.add(body, body, x, volume, block->materials[body]->density(), c, local,
                        Vec3::Zero());
    }
  });
  GridSettings settings;
  settings.kinematics = kinematics;
  if (fem_at) settings.fem_cells = fem;
  block->grid =
      std::make_unique<GridSystem>(block->mesh, block->topology, block->materials, settings);
  block->grid->initialise(block->points);
  return block;
}

}  // namespace geompm::testing
