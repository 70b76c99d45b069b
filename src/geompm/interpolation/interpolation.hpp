// How material points see the grid (docs/theory.md §§7-9): through the shape functions of their
// cell (standard MPM), or through a stencil wider than their cell, which the point integrator,
// the mapping, the loads and convect read alike: DDMP's node-averaged gradients (§8) or GIMP's
// weights over the point's domain (§9). Each interpolation is one file behind this interface, made
// by its name (interpolation_registry.cpp); CPDI would be one more.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include "geompm/core/communicator.hpp"
#include "geompm/mesh/mesh.hpp"
#include "geompm/points/material_points.hpp"

namespace geompm {

enum class GridInterpolation { Standard, DualDomain, Gimp };

/// Each point's wide stencil: its nodes (active ids, ascending), weights N and reference
/// gradients (dim per entry); point p spans [start[p], start[p + 1]).
struct WideStencils {
  std::vector<Index> start, nodes;
  std::vector<double> N, gradients;
  void clear(Index n_points) {
    start.assign(std::size_t(n_points) + 1, 0);
    nodes.clear();
    N.clear();
    gradients.clear();
  }
};

/// What an interpolation may read of the step's grid once its active nodes are known: each
/// point's shape values (nen per point) and reference gradients (nen x dim, column-major) in its
/// cell.
struct StencilInputs {
  const Mesh& mesh;
  const std::vector<Index>& node_to_active;
  Index active_nodes = 0;
  const std::vector<double>& shape;
  const std::vector<double>& gradients;
  /// The processes of a distributed run: each holds the points of its cells, and a node's sums
  /// over the points around it take every process's.
  const Communicator& processes = serial_communicator();
};

class Interpolation {
 public:
  virtual ~Interpolation() = default;
  virtual const char* name() const = 0;
  /// Whether points see nodes beyond their cell's; then `WideStencils` holds their stencils.
  virtual bool wide() const { return false; }
  /// Before the step's active cells are found: stencils that need no active numbering (mesh node
  /// ids), and every cell a stencil reaches marked occupied.
  virtual void before_activation(const MaterialPoints& /*points*/, std::vector<char>& /*occupied*/,
                                 WideStencils& /*out*/) const {}
  /// Once the active nodes and the cells' shape functions at the points are known: the
  /// stencils, in active node ids.
  virtual void after_activation(const MaterialPoints& /*points*/, const StencilInputs& /*in*/,
                                WideStencils& /*out*/) const {}
};

/// The interpolation `kind` on `mesh`, with the kinematics of the analysis. Throws
/// std::invalid_argument if the mesh does not suit it (GIMP on a mesh that is not a rectilinear
/// grid).
std::unique_ptr<Interpolation> make_interpolation(GridInterpolation kind, const Mesh& mesh,
                                                  Kinematics kinematics);
/// The name a model file gives it ("standard", "ddmp", "gimp").
const char* interpolation_name(GridInterpolation kind);

}  // namespace geompm
