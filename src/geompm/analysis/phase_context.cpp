#include "geompm/analysis/phase_context.hpp"

#include <fmt/format.h>

#include <algorithm>

#include "geompm/core/byte_archive.hpp"
#include "geompm/core/error.hpp"

namespace geompm {

PhaseContext::PhaseContext(const Model& model, const spec::Phase& phase) : spec(&phase) {
  fixities = resolve_fixities(model.mesh, phase.fixities);
  grid_motions = resolve_grid_motions(model.mesh, phase.grid_motions);
  for (const auto& m : phase.motions) {
    Motion motion;
    motion.set = model.point_set_bit(m.point_set);
    motion.velocity = m.velocity;
    for (int d = 0; d < 3; ++d)
      if (!m.components[d].empty())
        motion.components[d] = Expression(m.components[d], component_place(m.source, d));
    motions.push_back(std::move(motion));
  }
  for (const auto& l : phase.loads) {
    Load load;
    load.set = model.point_set_bit(l.point_set);
    for (int d = 0; d < 3; ++d)
      load.components[d] = Expression(l.components[d], component_place(l.source, d));
    loads.push_back(std::move(load));
  }
  for (const auto& structure : model.structures) {
    if (!structure->rigid()) {
      // A deformable structure: driven on sets of its nodes, several a phase (§17.7).
      std::vector<const spec::StructureDrive*> drives;
      for (const spec::StructureDrive& d : phase.structure_drives)
        if (d.structure == structure->name()) drives.push_back(&d);
      structure_drives.emplace_back(drives, structure->mesh());
      continue;
    }
    structure_drives.emplace_back(model.spec.kinematics);
    for (const spec::StructureDrive& d : phase.structure_drives)
      if (d.structure == structure->name())
        structure_drives.back() = StructureDrive(d, model.spec.kinematics);
  }
}

Vec3 PhaseContext::gravity(double t) const {
  if (!spec->gravity) return Vec3::Zero();
  const double factor = spec->gravity->ramp ? std::min(1.0, t / spec->duration) : 1.0;
  return factor * spec->gravity->acceleration;
}

Vec3 PhaseContext::motion_increment(const Motion& m, double t0, double t1) const {
  return prescribed_increment(m.components, m.velocity, t0, t1);
}

Vec3 PhaseContext::load(const Load& l, double t) const {
  return Vec3(l.components[0].at_time(t), l.components[1].at_time(t), l.components[2].at_time(t));
}

void PhaseContext::save(ByteWriter& out) const {
  out.put(static_cast<std::uint64_t>(motions.size()));
  for (const Motion& m : motions) out.put(m.done);
}

void PhaseContext::load(ByteReader& in) {
  const auto expect = [&](std::size_t here, const char* what) {
    const auto saved = in.get<std::uint64_t>();
    if (saved != here)
      throw InputError(fmt::format("{}: {} {} saved, the phase '{}' has {}", in.context(), saved,
                                   what, spec->name, here));
  };
  expect(motions.size(), "prescribed motions");
  for (Motion& m : motions) in.get(m.done);
  in.expect_end();
}

}  // namespace geompm
