#include "geompm/physics/pressure_field.hpp"

#include <algorithm>
#include <limits>

#include "geompm/physics/pressure_start_fit.hpp"

namespace geompm {

void PressureField::initialise(const GridSystem& grid, const MaterialPoints& points) {
  // The scales of the pressure unknowns (theory eq. 11.6) from the stiffest mixed soil of the
  // step, and the start value of the nodal pressures: the points' pressures (from the total
  // stress they carry) averaged onto the nodes with weights N v, so that Newton starts from the
  // last converged pressure field instead of from zero.
  const Index n_nodes = static_cast<Index>(grid.active_nodes().size());
  const auto& node_to_active = grid.node_to_active();
  double shear = 0.0, bulk = 0.0, size = 0.0;
  Index count = 0;
  start_ = Vector::Zero(n_nodes);
  Vector weight = Vector::Zero(n_nodes);
  for (Index p = 0; p < points.size(); ++p) {
    if (!grid.is_mixed(points, p)) continue;
    const ElasticModuli moduli =
        grid.materials()[points.material[p]]->elastic_moduli(points.internal[p]);
    shear = std::max(shear, moduli.shear);
    bulk = std::max(bulk, moduli.bulk);
    size += grid.cell_size(p);
    ++count;
    const double pressure = -points.stress[p].trace() / 3.0;
    const auto nodes = grid.mesh().cell_nodes(points.cell[p]);
    const double* N = grid.cell_shape(p);
    for (std::size_t a = 0; a < nodes.size(); ++a) {  // a mixed mesh's cells differ
      const double w = N[a] * points.volume[p];
      weight(node_to_active[nodes[a]]) += w;
      start_(node_to_active[nodes[a]]) += w * pressure;
    }
  }
  // In a distributed run each process has summed its own points: the nodes between processes
  // get every process's share, the scale the stiffest soil of every process's points.
  if (const Communicator& processes = grid.communicator(); processes.distributed()) {
    processes.sum(start_.data(), static_cast<std::size_t>(n_nodes));
    processes.sum(weight.data(), static_cast<std::size_t>(n_nodes));
    double sums[2] = {size, static_cast<double>(count)};
    processes.sum(sums, 2);
    size = sums[0];
    count = static_cast<Index>(sums[1]);
    double largest[2] = {shear, bulk};
    processes.max(largest, 2);
    shear = largest[0];
    bulk = largest[1];
  }
  for (Index a = 0; a < n_nodes; ++a)
    if (weight(a) > 0.0) start_(a) /= weight(a);
  scale_ = count > 0 ? shear / (size / count) : 1.0;
  reference_bulk_ = count > 0 ? bulk : 1.0;
  fitted_start_ = grid.settings().fitted_pressure_start;
  if (!fitted_start_) return;
  // Eq. 11.11: where the last converged field is known and the node's support is well filled,
  // start from that field smoothed by the local linear fit; elsewhere from the points.
  mark_supported_nodes(grid);
  if (last_.size() == std::size_t(grid.mesh().num_nodes()))
    fit_pressure_start(grid.mesh(), grid.active_cells(), grid.active_nodes(), node_to_active, last_,
                       supported_, start_);
}

void PressureField::mark_supported_nodes(const GridSystem& grid) {
  // A node is well supported when every cell around it is active and at least half filled by
  // mixed points: at the free surface, the heave and the footing's base its pressure is poorly
  // determined, and its last value would be carried on by the fit of eq. 11.11.
  const auto& active_nodes = grid.active_nodes();
  const auto& active_cells = grid.active_cells();
  const auto& node_to_active = grid.node_to_active();
  const Index n_nodes = static_cast<Index>(active_nodes.size());
  std::vector<Index> active_cells_around(n_nodes, 0);
  supported_.assign(n_nodes, 1);
  for (std::size_t ci = 0; ci < active_cells.size(); ++ci)
    for (Index node : grid.mesh().cell_nodes(active_cells[ci])) {
      const Index a = node_to_active[node];
      ++active_cells_around[a];
      if (grid.cell_mixed_fill()[ci] < 0.5) supported_[a] = 0;
    }
  for (Index a = 0; a < n_nodes; ++a)
    if (active_cells_around[a] < Index(grid.topology().node_cells.row(active_nodes[a]).size()))
      supported_[a] = 0;
}

Vector PressureField::nodal_pressure(const DofMap& dofs, const Vector& du) const {
  const int field = pressure_field(dofs);
  const Index n_nodes = static_cast<Index>(dofs.active_nodes().size());
  if (field < 0) return Vector::Zero(n_nodes);
  return start_ + scale_ * du.segment(dofs.dof(field, 0), n_nodes);
}

void PressureField::remember(const GridSystem& grid, const DofMap& dofs, const Vector& du) {
  if (!fitted_start_ || pressure_field(dofs) < 0) return;
  last_.assign(grid.mesh().num_nodes(), std::numeric_limits<double>::quiet_NaN());
  const Vector p = nodal_pressure(dofs, du);
  const auto& active_nodes = grid.active_nodes();
  for (std::size_t a = 0; a < active_nodes.size(); ++a)
    if (supported_[a]) last_[active_nodes[a]] = p(a);
}

}  // namespace geompm
