// A structure in the soil (docs/theory.md §17): a finite-element mesh of its own whose motion is
// a field of unknowns of each step's DofMap, named "structure:<name>". Contact (contact/) sees
// it through this interface only: the mesh and its boundary surface in the configuration at the
// start of the step, and the displacement increment of any of its points as weights of the
// step's unknowns, u(x) = sum_k coefficient_k du[dof_k] (linear in the unknowns within a step).
// RigidStructure implements it with one rigid-body motion; a deformable structure (nodal
// displacement unknowns, an updated-Lagrangian finite-element term) implements the same.
#pragma once

#include <string>
#include <vector>

#include "geompm/core/linear_algebra.hpp"
#include "geompm/core/types.hpp"
#include "geompm/dofs/dof_map.hpp"
#include "geompm/structures/structure_mesh.hpp"

namespace geompm {

class ByteWriter;
class ByteReader;

/// One unknown of the step and its weight in a point's displacement: u(x) = sum_k
/// coefficient_k * du[dof_k].
struct DofWeight {
  Index dof;
  Vec3 coefficient;
};

class Structure {
 public:
  Structure(std::string name, StructureMesh mesh)
      : name_(std::move(name)), mesh_(std::move(mesh)), initial_nodes_(mesh_.nodes()) {}
  virtual ~Structure() = default;

  const std::string& name() const { return name_; }
  virtual bool rigid() const = 0;
  /// Mesh and boundary surface in the current configuration (start of the step).
  const StructureMesh& mesh() const { return mesh_; }
  /// Adds its unknowns to the step's DofMap (before constraints are set / pattern built);
  /// returns the field id.
  virtual int add_unknowns(DofMap& dofs) const = 0;
  /// The displacement increment of the structure's point x (current configuration), `cell` the
  /// structure cell it lies in (or a boundary facet's cell), as weights of its unknowns.
  virtual void displacement_weights(const DofMap& dofs, const Vec3& x, Index cell,
                                    std::vector<DofWeight>& out) const = 0;
  /// The step converged with increment du (every unknown): move to the new configuration.
  /// Called once per converged step by the structure's own term (its Contribution::commit).
  virtual void commit(const DofMap& dofs, const Vector& du) = 0;

  // --- beyond what contact needs ----------------------------------------------------------------
  /// Its field's name in a step's DofMap.
  std::string field_name() const { return "structure:" + name_; }
  /// The node positions at the start of the analysis (the mesh's nodes minus these are the
  /// displacement written to ParaView).
  const std::vector<Vec3>& initial_nodes() const { return initial_nodes_; }
  /// A phase begins: what is measured since the phase start starts from here.
  virtual void start_phase() = 0;
  /// The state that carries over from step to step, for a checkpoint (load expects the same
  /// structure, as built from the same model).
  virtual void save(ByteWriter& out) const = 0;
  virtual void load(ByteReader& in) = 0;

 protected:
  /// Moves the nodes (the derived class's new configuration).
  void move_nodes(std::vector<Vec3> nodes) { mesh_.move_nodes(std::move(nodes)); }
  void restore_nodes(std::vector<Vec3> nodes) { mesh_.move_nodes(std::move(nodes)); }

 private:
  std::string name_;
  StructureMesh mesh_;
  std::vector<Vec3> initial_nodes_;
};

}  // namespace geompm
