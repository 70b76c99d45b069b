#include "geompm/structures/structure_builder.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "geompm/core/error.hpp"
#include "geompm/mesh/gmsh_import.hpp"
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

}  // namespace

std::unique_ptr<Structure> build_structure(const spec::Structure& s, Kinematics kinematics,
                                           const std::vector<spec::Phase>& phases) {
  const auto fail = [&s](const std::string& key, const std::string& what) -> InputError {
    return InputError(SourceLocation{s.source.file, s.source.key_path + key, s.source.line}, what);
  };
  if (!s.rigid)
    throw fail(".rigid",
               "deformable structures (rigid: false) are not yet supported; use rigid: true");
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
  double density = 0.0;
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
  return std::make_unique<RigidStructure>(s.name, std::move(structure_mesh), density,
                                          s.reference_point);
}

}  // namespace geompm
