// What a phase of the analysis prescribes, resolved against the model: fixities as node lists,
// motions and loads as compiled expressions of the phase time, gravity as a function of time.
#pragma once

#include <array>
#include <optional>
#include <vector>

#include "geompm/analysis/model.hpp"
#include "geompm/boundary/fixities.hpp"
#include "geompm/boundary/grid_motions.hpp"
#include "geompm/core/expression.hpp"
#include "geompm/structures/structure_drive.hpp"

namespace geompm {

struct PhaseContext {
  struct Motion {
    int set = 0;
    bool velocity = false;
    std::array<std::optional<Expression>, 3> components;  // empty = free
    Vec3 done = Vec3::Zero();  // prescribed displacement reached at the last converged step
  };
  struct Load {
    int set = 0;
    std::array<Expression, 3> components;
  };

  const spec::Phase* spec = nullptr;
  std::vector<ResolvedFixity> fixities;
  std::vector<ResolvedGridMotion> grid_motions;  // prescribed motion of grid nodes
  std::vector<Motion> motions;  // `done` is advanced by the step solver on convergence
  std::vector<Load> loads;
  /// Per structure of the model (in its order), how the phase drives it (free if not listed).
  std::vector<StructureDrive> structure_drives;

  PhaseContext(const Model& model, const spec::Phase& phase);

  /// Gravity at phase time t (ramped linearly over the phase if asked).
  Vec3 gravity(double t) const;
  /// Prescribed displacement increment of motion m over [t0, t1], per component (NaN = free).
  Vec3 motion_increment(const Motion& m, double t0, double t1) const;
  /// Force of load l at phase time t.
  Vec3 load(const Load& l, double t) const;

  /// What persists from step to step (the motions' `done`), for a
  /// checkpoint; load() expects the phase the checkpoint was written in.
  void save(ByteWriter& out) const;
  void load(ByteReader& in);
};

}  // namespace geompm
