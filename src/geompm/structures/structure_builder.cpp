#include "geompm/structures/structure_builder.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "geompm/core/error.hpp"
#include "geompm/mesh/gmsh_import.hpp"
#include "geompm/structures/deformable_structure.hpp"
#include "geompm/structures/node_selection.hpp"
#include "geompm/structures/rigid_structure.hpp"
#include "geompm/structures/shapes.hpp"

namespace geompm {

namespace {

// The magnitude of the gravity of the first phase that has one (a weight's mass is W / g).
double first_gravity(const std::vector<spec::Phase>& phases) {
  for (const spec::Phase& phase : phases)
    if (phase.gravity && phase.gravity->acceleration.norm() > 0)
      return phase.gravity->acceleration.norm();
  return 0.0;
}

// The phase drives of a deformable structure select some of its nodes (checked here, before
// the run, rather than when the phase starts).
void check_drives(const spec::Structure& s, const StructureMesh& mesh,
                  const std::vector<spec::Phase>& phases) {
  for (const spec::Phase& phase : phases)
    for (const spec::StructureDrive& drive : phase.structure_drives)
      if (drive.structure == s.name && drive.nodes) select_nodes(mesh, *drive.nodes);
}

}  // namespace

std::unique_ptr<Structure> build_structure(const spec::Structure& s, const spec::Model& model,
                                           const std::vector<const Material*>& materials) {
  const auto fail = [&s](const std::string& key, const std::string& what) -> InputError {
    return InputError(SourceLocation{s.source.file, s.source.key_path + key, s.source.line}, what);
  };
  const Kinematics kinematics = model.kinematics;
  const std::vector<spec::Phase>& phases = model.phases;
  Mesh mesh;
  try {
    mesh = s.shape ? shape_mesh(*s.shape, kinematics)
                   : read_gmsh_mesh(s.mesh_file, spatial_dimension(kinematics));
  } catch (const InputError& e) {
    throw fail(".mesh", e.what());
  } catch (const std::exception& e) {
    throw fail(".shape", e.what());
  }
  StructureMesh structure_mesh;
  try {
    structure_mesh = StructureMesh(std::move(mesh), kinematics);
  } catch (const std::invalid_argument& e) {
    throw fail(s.shape ? ".shape" : ".mesh", e.what());
  }
  const double volume = structure_mesh.measure();
  const Material* material = nullptr;
  for (std::size_t m = 0; m < model.materials.size(); ++m)
    if (!s.rigid && model.materials[m].name == s.material) material = materials[m];
  if (!s.rigid && !material)
    throw fail(".deformable.material", "no material named '" + s.material + "'");
  double density = material ? material->density() : 0.0;
  if (s.density) {
    density = *s.density;
  } else if (s.mass) {
    density = *s.mass / volume;
  } else if (s.weight) {
    const double g = first_gravity(phases);
    if (!(g > 0))
      throw fail(".weight",
                 "a weight is turned into a mass by the gravity, and no phase has one: give the "
                 "structure's density or mass instead");
    density = *s.weight / (g * volume);
  }
  if (!s.rigid) {
    check_drives(s, structure_mesh, phases);
    return std::make_unique<DeformableStructure>(s.name, std::move(structure_mesh), *material,
                                                 density);
  }
  return std::make_unique<RigidStructure>(s.name, std::move(structure_mesh), density,
                                          s.reference_point);
}

}  // namespace geompm
