#include "geompm/dofs/dof_map.hpp"

#include <stdexcept>

namespace geompm {

int DofMap::add_nodal_field(std::string name, FieldKind kind, int components) {
  const int f =
      add_field(std::move(name), kind, static_cast<Index>(active_nodes_.size()), components);
  fields_[f].nodal = true;
  return f;
}

int DofMap::add_field(std::string name, FieldKind kind, Index entities, int components) {
  if (find(name) >= 0) throw std::logic_error("DofMap: a second field named '" + name + "'");
  fields_.push_back({std::move(name), kind, false, entities, components, size_});
  size_ += entities * components;
  constrained_.assign(size_, 0);
  prescribed_ = Eigen::VectorXd::Zero(size_);
  free_index_.clear();
  free_dof_.clear();
  num_free_ = 0;
  return num_fields() - 1;
}

int DofMap::find(std::string_view name) const {
  for (int f = 0; f < num_fields(); ++f)
    if (fields_[f].name == name) return f;
  return -1;
}

Unknown DofMap::unknown(Index dof) const {
  for (int f = num_fields() - 1; f >= 0; --f) {
    const Field& field = fields_[f];
    if (dof >= field.offset && field.components > 0) {
      const Index local = dof - field.offset;
      return {f, local / field.components, static_cast<int>(local % field.components)};
    }
  }
  return {};
}

void DofMap::constrain(Index dof, double value) {
  constrained_[dof] = 1;
  prescribed_(dof) = value;
}

void DofMap::number_free() {
  free_index_.assign(size_, -1);
  free_dof_.clear();
  for (Index d = 0; d < size_; ++d)
    if (!constrained_[d]) {
      free_index_[d] = static_cast<Index>(free_dof_.size());
      free_dof_.push_back(d);
    }
  num_free_ = static_cast<Index>(free_dof_.size());
}

void DofMap::expand(const Eigen::VectorXd& x, Eigen::VectorXd& all) const {
  all = prescribed_;
  for (Index k = 0; k < num_free_; ++k) all(free_dof_[k]) = x(k);
}

void DofMap::restrict_to_free(const Eigen::VectorXd& all, Eigen::VectorXd& x) const {
  x.resize(num_free_);
  for (Index k = 0; k < num_free_; ++k) x(k) = all(free_dof_[k]);
}

}  // namespace geompm
