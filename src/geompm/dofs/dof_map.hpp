// The unknowns of a step (docs/architecture.md, "Unknowns"): named fields, each a block of
// unknowns numbered one after another, entity-major within its block (unknown = offset + entity *
// components + component). Nodal fields have the step's active nodes as entities: the
// displacement increment (dim per node) and, with the mixed p-u formulation, the scaled pressure
// change (one per node, theory eq. 11.6); structure nodes, rigid-body motions and contact
// multipliers are more fields of the same map. It also holds which unknowns are constrained,
// with the values prescribed for them, and numbers the free ones for the linear solver. Nothing
// else computes an unknown's index.
#pragma once

#include <Eigen/Core>
#include <string>
#include <string_view>
#include <vector>

#include "geompm/core/types.hpp"

namespace geompm {

/// What a field's unknowns are, for what a linear solver may want to know of them (the
/// displacement block and its rigid-body modes for AMG, the pressure block for a Schur split).
enum class FieldKind { Displacement, Pressure, Other };

struct Field {
  std::string name;
  FieldKind kind = FieldKind::Other;
  bool nodal = false;  // entities are the step's active nodes
  Index entities = 0;
  int components = 0;
  Index offset = 0;  // the field's first unknown
};

/// An unknown as what it is: its field, entity (an active node for nodal fields) and component.
struct Unknown {
  int field = -1;
  Index entity = -1;
  int component = -1;
};

class DofMap {
 public:
  DofMap() = default;
  /// `active_nodes`: the mesh node of each active node of the step, the entities of nodal fields.
  explicit DofMap(std::vector<Index> active_nodes) : active_nodes_(std::move(active_nodes)) {}

  /// A field of `components` unknowns at every active node, numbered after the fields before it.
  int add_nodal_field(std::string name, FieldKind kind, int components);
  /// A field of `components` unknowns on each of `entities` entities of its own.
  int add_field(std::string name, FieldKind kind, Index entities, int components);
  /// The field's id, or -1 if the map has no field of that name.
  int find(std::string_view name) const;
  int num_fields() const { return static_cast<int>(fields_.size()); }
  const Field& field(int f) const { return fields_[f]; }
  /// Every unknown, constrained or free.
  Index size() const { return size_; }

  Index dof(int field, Index entity, int component = 0) const {
    const Field& f = fields_[field];
    return f.offset + entity * f.components + component;
  }
  Unknown unknown(Index dof) const;
  const std::vector<Index>& active_nodes() const { return active_nodes_; }

  // --- constraints ---------------------------------------------------------------------------
  /// The unknown is prescribed: its value over the step is `value` (a later call wins).
  void constrain(Index dof, double value = 0.0);
  bool constrained(Index dof) const { return constrained_[dof] != 0; }
  /// Per unknown: 1 if constrained.
  const std::vector<char>& constraint_flags() const { return constrained_; }
  /// Per unknown: its prescribed value where constrained, 0 elsewhere.
  const Eigen::VectorXd& prescribed() const { return prescribed_; }
  /// Numbers the free unknowns in the order of the unknowns; call once the constraints are set.
  void number_free();
  Index num_free() const { return num_free_; }
  /// The unknown's free index, or -1 if it is constrained.
  Index free_index(Index dof) const { return free_index_[dof]; }
  const std::vector<Index>& free_indices() const { return free_index_; }
  /// The unknown of a free index (the inverse of free_index).
  Index dof_of_free(Index free) const { return free_dof_[free]; }

  /// x (free unknowns) into `all` (every unknown): free entries from x, constrained ones their
  /// prescribed values.
  void expand(const Eigen::VectorXd& x, Eigen::VectorXd& all) const;
  /// The free entries of `all`.
  void restrict_to_free(const Eigen::VectorXd& all, Eigen::VectorXd& x) const;

 private:
  std::vector<Index> active_nodes_;
  std::vector<Field> fields_;
  Index size_ = 0;
  std::vector<char> constrained_;
  Eigen::VectorXd prescribed_;
  Index num_free_ = 0;
  std::vector<Index> free_index_, free_dof_;
};

}  // namespace geompm
