// The pieces of the model reader (private to io/): one reader per section of the model file, and
// the checks on single values that several sections share. read_model() in model_reader.cpp
// calls the sections in file order; each section adds the names it defines to the Context so
// that later sections can check their references (a body's material, a load's point set).
#pragma once

#include <array>
#include <map>
#include <optional>
#include <string>
#include <vector>

#include "geompm/io/yaml_access.hpp"
#include "geompm/mesh/cell_type.hpp"
#include "geompm/spec/model_spec.hpp"

namespace geompm::model_reader {

struct Context {
  Kinematics kinematics = Kinematics::PlaneStrain;
  int dimension = 2;
  /// Known for a generated mesh; an imported mesh's cell type is known only after import.
  std::optional<CellType> cell_type;
  /// Boundaries of a generated mesh; empty for an imported mesh (its names are checked after
  /// import, when its physical groups are known).
  std::vector<std::string> boundaries;
  std::vector<std::string> materials;
  /// Materials whose model has a default K0 (mohr_coulomb: 1 - sin phi).
  std::vector<std::string> materials_with_default_k0;
  std::vector<std::string> bodies;
  /// The materials of each body (one, or those of its layers).
  std::map<std::string, std::vector<std::string>> body_materials;
  std::vector<std::string> point_sets;
  /// Named node sets: boundaries too (read_boundary_name accepts them).
  std::vector<std::string> node_sets;
  /// Structures (the top-level list), and those of them that are deformable.
  std::vector<std::string> structures;
  std::vector<std::string> deformable_structures;
};

// Sections, in file order.
spec::Mesh read_mesh(const yaml::Node& node, const std::string& model_directory, Context& context);
/// The kinds of the mesh's cells (model_reader_regions.cpp).
std::vector<spec::MeshRegion> read_regions(const yaml::Node& node, const Context& context);
std::vector<spec::Material> read_materials(const yaml::Node& node, Context& context);
spec::Region read_region(const yaml::Node& node, const Context& context);
/// A body's `initial_stress` (model_reader_initial_stress.cpp).
spec::InitialStress read_initial_stress(const yaml::Node& node, const Context& context);
std::vector<spec::Body> read_bodies(const yaml::Node& node, Context& context);
std::vector<spec::PointSet> read_point_sets(const yaml::Node& node, Context& context);
std::vector<spec::NodeSet> read_node_sets(const yaml::Node& node, Context& context);
std::vector<spec::Phase> read_phases(const yaml::Node& node, Context& context);
/// The phase's expressions of time evaluated at its start and end; a non-finite value is an
/// InputError naming the expression and its place (model_reader_phase_values.cpp).
void check_phase_expressions(const spec::Phase& phase);
/// A phase's `surface_loads` (model_reader_surface_loads.cpp).
std::vector<spec::SurfaceLoad> read_surface_loads(const yaml::Node& node, const Context& context);
spec::Output read_output(const yaml::Node& node, const Context& context);
spec::Numerics read_numerics(const yaml::Node& node);
// Structures (model_reader_structures.cpp): the top-level list, a phase's drives, a history.
/// A structure's `contact` (model_reader_contact.cpp).
spec::Contact read_contact(const yaml::Node& node, const Context& context);
std::vector<spec::Structure> read_structures(const yaml::Node& node, const std::string& directory,
                                             Context& context);
std::vector<spec::StructureDrive> read_structure_drives(const yaml::Node& node,
                                                        const Context& context);
/// Some nodes of a deformable structure (model_reader_structures.cpp).
spec::StructureNodes read_structure_nodes(const yaml::Node& node, const Context& context);
void read_structure_history(const yaml::Map& section, const Context& context,
                            spec::History& history);

// Shared value checks; each fails at the node with what was expected and what was found.

/// x, y, z or 0, 1, 2, within the dimension.
int read_component(const yaml::Node& node, int dimension);
/// "x", "y", "z"
const char* component_name(int component);

/// An expression (a number or a muparser formula) that compiles and uses only `variables`.
std::string read_expression(const yaml::Node& node, const std::vector<std::string>& variables);

/// A list of `dimension` expressions; with `free_allowed`, a null (~) item is a free component
/// and is returned as "". Components beyond the dimension are `unused`.
std::array<std::string, 3> read_expression_vector(const yaml::Node& node, int dimension,
                                                  const std::vector<std::string>& variables,
                                                  bool free_allowed, const std::string& unused);

/// A name that must be one of `defined` ("material", "body", "point set" for messages).
std::string read_reference(const yaml::Node& node, const std::string& kind,
                           const std::vector<std::string>& defined);

/// A boundary name: a node set, or for a generated mesh one of its boundaries; for an imported
/// mesh any name (checked when the mesh is read).
std::string read_boundary_name(const yaml::Node& node, const Context& context);

/// Numbers with a range, failing with the range in the message.
double read_positive(const yaml::Node& node);
double read_non_negative(const yaml::Node& node);

/// A fraction 0 < fill <= 1 of `what` (named in the error).
double read_fill_fraction(const yaml::Node& node, const std::string& what);

}  // namespace geompm::model_reader
