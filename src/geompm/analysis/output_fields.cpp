#include "geompm/analysis/output_fields.hpp"

#include <cmath>
#include <string_view>

#include "geompm/core/tensor.hpp"

namespace geompm {

std::vector<double> equivalent_plastic_strain(const Model& model, const MaterialPoints& p) {
  // Where each material keeps it, -1 where it does not.
  std::vector<int> slot(model.materials.size(), -1);
  for (std::size_t m = 0; m < model.materials.size(); ++m)
    for (int k = 0; k < model.materials[m]->internal_variable_count(); ++k)
      if (std::string_view(model.materials[m]->internal_variable_name(k)) ==
          "equivalent_plastic_strain")
        slot[m] = k;
  std::vector<double> strain(p.size(), 0.0);
  for (Index i = 0; i < p.size(); ++i) {
    const int k = slot[p.material[i]];
    if (k >= 0) strain[i] = p.internal[i][k];
  }
  return strain;
}

FieldSet point_fields(const Model& model, const MaterialPoints& p,
                      const std::vector<Index>& plastic) {
  const Index n = p.size();
  FieldSet f;
  f.vectors.emplace_back("displacement", p.displacement);
  f.vectors.emplace_back("velocity", p.velocity);
  f.vectors.emplace_back("acceleration", p.acceleration);
  f.tensors.emplace_back("stress", p.stress);
  std::vector<Mat3> strain(n);
  std::vector<double> mean(n), q(n);
  for (Index i = 0; i < n; ++i) {
    const Mat3& F = p.deformation_gradient[i];
    strain[i] = 0.5 * symmetric_log(F * F.transpose());
    mean[i] = p.stress[i].trace() / 3.0;
    const Mat3 s = p.stress[i] - mean[i] * Mat3::Identity();
    q[i] = std::sqrt(1.5 * s.squaredNorm());
  }
  f.tensors.emplace_back("strain", std::move(strain));
  f.scalars.emplace_back("mean_stress", std::move(mean));
  f.scalars.emplace_back("deviatoric_stress", std::move(q));
  f.scalars.emplace_back("equivalent_plastic_strain", equivalent_plastic_strain(model, p));
  std::vector<Index> flag(n, 0);
  if (static_cast<Index>(plastic.size()) == n) flag = plastic;
  f.integers.emplace_back("plastic", std::move(flag));
  f.scalars.emplace_back("volume", p.volume);
  f.scalars.emplace_back("mass", p.mass);
  f.integers.emplace_back("id", p.id);
  f.integers.emplace_back("body", p.body);
  f.integers.emplace_back("material", p.material);
  return f;
}

void grid_fields(const Model& model, const GridSystem& grid, const StepResult& step,
                 FieldSet& node_fields, FieldSet& cell_fields) {
  const Index n_nodes = model.mesh.num_nodes();
  const int dim = grid.dim();
  std::vector<Vec3> velocity(n_nodes, Vec3::Zero()), displacement(n_nodes, Vec3::Zero());
  std::vector<double> mass(n_nodes, 0.0);
  const auto& active = grid.active_nodes();
  const DofMap& dofs = *step.dofs;
  const int u = dofs.find("displacement");
  for (Index a = 0; a < static_cast<Index>(active.size()); ++a) {
    for (int i = 0; i < dim; ++i) {
      velocity[active[a]](i) = step.velocity(dofs.dof(u, a, i));
      displacement[active[a]](i) = step.displacement(dofs.dof(u, a, i));
    }
    mass[active[a]] = grid.nodal_mass()(a);
  }
  node_fields.vectors.emplace_back("velocity", std::move(velocity));
  node_fields.vectors.emplace_back("step_displacement", std::move(displacement));
  node_fields.scalars.emplace_back("mass", std::move(mass));
  if (step.nodal_pressure.size() > 0) {
    // The pressure unknowns of the mixed formulation (compression positive; theory eq. 11.6).
    std::vector<double> pressure(n_nodes, 0.0);
    for (Index a = 0; a < static_cast<Index>(active.size()); ++a)
      pressure[active[a]] = step.nodal_pressure(a);
    node_fields.scalars.emplace_back("pressure", std::move(pressure));
  }

  std::vector<Index> is_active(model.mesh.num_cells(), 0);
  std::vector<double> fill(model.mesh.num_cells(), 0.0);
  for (std::size_t k = 0; k < grid.active_cells().size(); ++k) {
    is_active[grid.active_cells()[k]] = 1;
    fill[grid.active_cells()[k]] = grid.cell_fill()[k];
  }
  cell_fields.integers.emplace_back("active", std::move(is_active));
  cell_fields.scalars.emplace_back("fill", std::move(fill));
  if (model.cell_kinds.empty()) return;
  // With `regions`, each cell's kind (0 MPM, 1 FEM, 2 buffer: CellKind's order), to colour by.
  std::vector<Index> kind;
  for (CellKind k : model.cell_kinds) kind.push_back(static_cast<Index>(k));
  cell_fields.integers.emplace_back("cell_kind", std::move(kind));
}

}  // namespace geompm
