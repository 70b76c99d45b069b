#include "geompm/structures/deformable_structure.hpp"

#include <Eigen/LU>

#include "geompm/core/byte_archive.hpp"
#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/structures/structure_quadrature.hpp"

namespace geompm {

DeformableStructure::DeformableStructure(std::string name, StructureMesh mesh,
                                         const Material& material, double density)
    : Structure(std::move(name), std::move(mesh)),
      material_(material),
      density_(density),
      phase_nodes_(this->mesh().nodes()) {
  points_per_cell_ = dispatch_cell_type(this->mesh().mesh().cell_type,
                                        [](auto e) { return decltype(e)::quadrature_size(); });
  const std::size_t n = static_cast<std::size_t>(this->mesh().num_cells() * points_per_cell_);
  gauss_.resize(n);
  gauss_mass_.resize(n);
  // The mass of a Gauss point is that of its share of the initial configuration, and stays so
  // (eq. 17.13); a material whose properties vary in space stores them at the point.
  for_each_gauss_point(this->mesh(), [&](Index c, int q, const Vec3& x, double w) {
    const std::size_t k = static_cast<std::size_t>(c * points_per_cell_ + q);
    gauss_mass_[k] = density_ * w;
    material_.initialise_point(x, dim(), gauss_[k].internal);
  });
  velocity_ = acceleration_ = Vector::Zero(num_nodes() * dim());
}

int DeformableStructure::add_unknowns(DofMap& dofs) const {
  return dofs.add_field(field_name(), FieldKind::Other, num_nodes(), dim());
}

Index DeformableStructure::dof(const DofMap& dofs, Index node, int i) const {
  return dofs.dof(dofs.find(field_name()), node, i);
}

Vector DeformableStructure::nodal(const DofMap& dofs, const Vector& du) const {
  const int field = dofs.find(field_name());
  const Index offset = dofs.field(field).offset;
  return du.segment(offset, num_nodes() * dim());
}

void DeformableStructure::displacement_weights(const DofMap& dofs, const Vec3& x, Index cell,
                                               std::vector<DofWeight>& out) const {
  // u(x) = sum_a N_a(xi) du_a with xi the reference coordinates of x in its cell (eq. 17.11); a
  // point of a boundary facet lies on the facet's cell.
  out.clear();
  const int field = dofs.find(field_name());
  const Mesh& mesh = this->mesh().mesh();
  const std::optional<Vec3> xi = map_to_reference(mesh, cell, x);
  dispatch_cell_type(mesh.cell_type, [&](auto element) {
    using E = decltype(element);
    const typename E::Local local = xi ? typename E::Local(xi->head<E::dim>()) : E::centroid();
    const typename E::Values N = E::shape(local);
    const auto nodes = mesh.cell_nodes(cell);
    for (int a = 0; a < E::nodes; ++a)
      for (int i = 0; i < E::dim; ++i)
        out.push_back({dofs.dof(field, nodes[a], i), N(a) * Vec3::Unit(i)});
  });
}

void DeformableStructure::commit(const DofMap& dofs, const Vector& du) {
  // Updated Lagrangian: the converged configuration is the next step's reference.
  const Vector u = nodal(dofs, du);
  std::vector<Vec3> nodes = mesh().nodes();
  for (Index a = 0; a < num_nodes(); ++a)
    for (int i = 0; i < dim(); ++i) nodes[a](i) += u(a * dim() + i);
  move_nodes(std::move(nodes));
}

void DeformableStructure::start_phase() { phase_nodes_ = mesh().nodes(); }

double DeformableStructure::mass() const {
  double m = 0.0;
  for (double mq : gauss_mass_) m += mq;
  return m;
}

std::vector<Mat3> DeformableStructure::cell_stress() const {
  std::vector<Mat3> stress(static_cast<std::size_t>(mesh().num_cells()), Mat3::Zero());
  std::vector<double> volume(stress.size(), 0.0);
  for_each_gauss_point(mesh(), [&](Index c, int q, const Vec3&, double w) {
    stress[c] += w * gauss_[static_cast<std::size_t>(c * points_per_cell_ + q)].stress;
    volume[c] += w;
  });
  for (std::size_t c = 0; c < stress.size(); ++c) stress[c] /= volume[c];
  return stress;
}

void DeformableStructure::set_rates(Vector velocity, Vector acceleration) {
  velocity_ = std::move(velocity);
  acceleration_ = std::move(acceleration);
}

void DeformableStructure::save(ByteWriter& out) const {
  out.put(mesh().nodes());
  out.put(phase_nodes_);
  std::vector<Mat3> F, be, stress;
  std::vector<InternalVariables> internal;
  for (const GaussPointState& g : gauss_) {
    F.push_back(g.F);
    be.push_back(g.be);
    stress.push_back(g.stress);
    internal.push_back(g.internal);
  }
  out.put(F);
  out.put(be);
  out.put(internal);
  out.put(stress);
  out.put(std::vector<double>(velocity_.begin(), velocity_.end()));
  out.put(std::vector<double>(acceleration_.begin(), acceleration_.end()));
}

void DeformableStructure::load(ByteReader& in) {
  restore_nodes(in.get<std::vector<Vec3>>());
  in.get(phase_nodes_);
  const auto F = in.get<std::vector<Mat3>>(), be = in.get<std::vector<Mat3>>();
  const auto internal = in.get<std::vector<InternalVariables>>();
  const auto stress = in.get<std::vector<Mat3>>();
  gauss_.resize(F.size());
  for (std::size_t k = 0; k < F.size(); ++k) gauss_[k] = {F[k], be[k], internal[k], stress[k]};
  const auto v = in.get<std::vector<double>>(), a = in.get<std::vector<double>>();
  velocity_ = Eigen::Map<const Vector>(v.data(), static_cast<Index>(v.size()));
  acceleration_ = Eigen::Map<const Vector>(a.data(), static_cast<Index>(a.size()));
}

}  // namespace geompm
