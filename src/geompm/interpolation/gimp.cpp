#include "geompm/interpolation/gimp.hpp"

#include <stdexcept>
#include <string>

#include "geompm/interpolation/gimp_weights.hpp"

namespace geompm {
namespace {
RectilinearGrid rectilinear_grid_of(const Mesh& mesh) {
  std::string why;
  auto grid = find_rectilinear_grid(mesh, why);
  if (!grid)
    throw std::invalid_argument("numerics.interpolation: gimp needs a rectilinear grid, but " +
                                why);
  return *grid;
}
}  // namespace

Gimp::Gimp(const Mesh& mesh, Kinematics kinematics)
    : grid_(rectilinear_grid_of(mesh)), kinematics_(kinematics), dim_(mesh.dim()) {}

void Gimp::before_activation(const MaterialPoints& points, std::vector<char>& occupied,
                             WideStencils& out) const {
  // Each point's domain: the seeded half-lengths stretched with the diagonal of its domain's F
  // (cpGIMP, eq. 9.4; with a volume average the domain follows the point's own motion, eq. 12.7),
  // clipped to the grid (eq. 9.5); weights and gradients eq. 9.1-9.3 on the grid at
  // the start of the step. Node ids are the mesh's here (initialise renumbers them); every
  // cell the domain overlaps is marked occupied.
  const RectilinearGrid& grid = grid_;
  const bool axisymmetric = kinematics_ == Kinematics::Axisymmetric;
  const Index n_points = points.size();
  out.clear(n_points);
  GimpStencil s;
  for (Index p = 0; p < n_points; ++p) {
    const Vec3 half = particle_half_lengths(points.initial_half_size[p],
                                            points.domain_deformation(p, dim_), dim_);
    gimp_stencil(grid, points.position[p], half, points.cell[p], axisymmetric, s);
    out.nodes.insert(out.nodes.end(), s.nodes.begin(), s.nodes.end());
    out.N.insert(out.N.end(), s.N.begin(), s.N.end());
    out.gradients.insert(out.gradients.end(), s.gradients.begin(), s.gradients.end());
    out.start[p + 1] = static_cast<Index>(out.nodes.size());
    for (int k = s.first_cell[2]; k <= s.last_cell[2]; ++k)
      for (int j = s.first_cell[1]; j <= s.last_cell[1]; ++j)
        for (int i = s.first_cell[0]; i <= s.last_cell[0]; ++i) occupied[grid.cell(i, j, k)] = 1;
  }
}

void Gimp::after_activation(const MaterialPoints& /*points*/, const StencilInputs& in,
                            WideStencils& out) const {
  // Stencils were built with mesh node ids, ascending; active ids keep their order.
  for (Index& node : out.nodes) node = in.node_to_active[node];
}

}  // namespace geompm
