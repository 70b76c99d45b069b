// The model as the engine sees it: the mesh and its topology, the materials, the material points
// seeded into the bodies, and the named point sets; built from the spec read from a model file.
#pragma once

#include <map>
#include <memory>
#include <string>
#include <vector>

#include "geompm/contact/contact_pair.hpp"
#include "geompm/core/communicator.hpp"
#include "geompm/coupling/fem_region.hpp"
#include "geompm/materials/material.hpp"
#include "geompm/mesh/mesh.hpp"
#include "geompm/mesh/mesh_topology.hpp"
#include "geompm/mesh/point_locator.hpp"
#include "geompm/points/material_points.hpp"
#include "geompm/spec/model_spec.hpp"
#include "geompm/structures/structure.hpp"

namespace geompm {

class ByteWriter;
class ByteReader;

struct Model {
  spec::Model spec;
  Mesh mesh;
  MeshTopology topology;
  std::unique_ptr<PointLocator> locator;
  std::vector<std::unique_ptr<Material>> materials;  // in the order of spec.materials
  MaterialPoints points;
  /// Per mesh cell, its kind (MPM, FEM, buffer: docs/theory.md §19); empty when every cell is MPM.
  std::vector<CellKind> cell_kinds;
  /// The FEM cells and their Gauss points; null without FEM cells.
  std::unique_ptr<FemRegion> fem;
  std::vector<std::string> point_set_names;  // bit k of MaterialPoints::sets
  /// Per mesh cell, the process that owns it in a distributed run, cut by the points seeding puts
  /// in each cell (a resumed run: the checkpoint's): `points` holds only this process's cells'.
  /// Empty when the model is built for one process (mesh/partition.hpp).
  std::vector<int> cell_part;
  /// The structures (docs/theory.md §17), in the order of spec.structures; they move with the
  /// steps that converge (their state is saved by Structure::save).
  std::vector<std::unique_ptr<Structure>> structures;
  /// The contact of each structure with the soil (docs/theory.md §18), in the same order.
  std::vector<ContactPair> contacts;
  /// Displacement prescribed so far on the nodes of each driven boundary or node set (grid
  /// motions, summed over the phases; components never driven stay 0), for histories.
  std::map<std::string, Vec3> grid_displacement;
  double lost_mass = 0.0;  // of points removed after leaving the mesh
  Index lost_points = 0;
  /// Per body: the seeding positions left out because they lie inside a structure (a structure
  /// that starts embedded in the soil, "wished in place").
  std::vector<Index> seeds_inside_structures;

  Kinematics kinematics() const { return spec.kinematics; }
  /// What a run changes besides the points (displacements so far, lost points), for a
  /// checkpoint; the points are saved by MaterialPoints::save.
  void save_state(ByteWriter& out) const;
  /// What save_state writes before the FEM region's Gauss points, which come last (saved by
  /// MaterialPoints::save; a distributed run streams them: analysis/simulation_state.cpp).
  void save_state_before_gauss_points(ByteWriter& out) const;
  void load_state(ByteReader& in);
  std::vector<const Material*> material_pointers() const;
  int point_set_bit(const std::string& name) const;  // -1 if unknown
  /// The largest reference modulus of the materials the points carry (the scale of contact's
  /// multipliers). In a distributed run, pass its processes: the points of every process count
  /// (collective), not only this process's.
  double largest_modulus(const Communicator& processes = serial_communicator()) const;
  /// The smallest reference modulus of the materials the points carry: the soil's, the scale of
  /// the empty cells' and sparse nodes' stiffness (a steel block among the points must not
  /// stiffen the empty cells beside the soil). `processes` as for largest_modulus.
  double softest_modulus(const Communicator& processes = serial_communicator()) const;
};

/// The material (index into spec.materials) of `body` at `elevation` (y in 2D, z in 3D): its one
/// material, or that of the layer holding the elevation (a layer holds its bottom; the last
/// layer everything below).
Index body_material_at(const spec::Model& spec, const spec::Body& body, double elevation);

/// Builds the mesh (generated or imported), checks it, creates the materials, seeds the bodies and
/// selects the point sets. Throws InputError naming the model file, key path and line for
/// anything the reader could not check alone (a region group the mesh lacks, a body outside the
/// mesh or with no points, overlapping bodies, an empty point set, a fixity boundary the mesh
/// lacks, a node set holding no node, a node driven twice).
///
/// Given the processes of a distributed run (collective), each builds the same model but seeds
/// only the points of its own cells (`cell_part`), with the ids and values of the serial run;
/// every process then throws the same error for bad input.
std::unique_ptr<Model> build_model(const spec::Model& spec,
                                   const Communicator& processes = serial_communicator());

/// The summary `geompm check` and `geompm run` print: mesh, points, materials, bodies, phases.
/// In a distributed run, pass its processes: the counts and sums are of every process's points
/// (collective).
std::string describe_model(const Model& model,
                           const Communicator& processes = serial_communicator());

}  // namespace geompm
