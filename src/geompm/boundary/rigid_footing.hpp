// A rigid footing acting on the soil by penalty contact at the material points (docs/theory.md
// §13): a rigid body with a flat horizontal base (a strip or plate in plane strain and 3D, a
// disc in axisymmetry) whose position is prescribed as a function of the phase time. Each soil
// point whose domain reaches through the base is pushed back by a normal penalty force in
// proportion to its penetration and to the part of its domain under the footprint; a rough base
// also ties the point's horizontal displacement to the footing's from its first contact on.
#pragma once

#include <array>
#include <optional>
#include <string>
#include <unordered_map>

#include "geompm/core/expression.hpp"
#include "geompm/spec/model_spec.hpp"

namespace geompm {

class ByteWriter;
class ByteReader;

/// Where the footing is at one instant: the elevation of its base, its footprint [low_t,
/// high_t] along each horizontal axis t (x in 2D, the radius in axisymmetry; x and y in 3D) and
/// its displacement since the start of the phase.
struct FootingPose {
  double base = 0.0;
  Vec3 low = Vec3::Zero(), high = Vec3::Zero();
  Vec3 displacement = Vec3::Zero();
};

/// A soil point as the contact sees it within a step: its position and domain half-lengths at
/// the start of the step, its penalty kappa (stress per unit penetration) and, on a rough base,
/// where it sticks (its horizontal position relative to the footing at its first contact).
struct FootingContactPoint {
  Vec3 position = Vec3::Zero();
  Vec3 half = Vec3::Zero();
  double kappa = 0.0;
  bool rough = false;
  /// Held in contact in both directions (ContactHold): touching at the start of the step (eq.
  /// 13.8), or come into contact a second time in the step's Newton iterates (eq. 13.9), so that
  /// its contact does not flip on and off from one iteration to the next; released at the end of
  /// a step that leaves it in tension.
  bool bilateral = false;
  /// Rough: where the point sticks. `anchored`: it stuck at the end of the last step (the anchor
  /// kept, eq. 13.4); otherwise the anchor is its position at the start of the step and
  /// `start_gap` the gap g it had to the footing's base then (< 0: below it), from which the
  /// place it first touches along the step is found (eq. 13.4a).
  bool anchored = false;
  double start_gap = 0.0;
  Vec3 anchor = Vec3::Zero();
};

/// The contact force on a point at its displacement increment u (eqs. 13.1-13.5).
struct FootingContactForce {
  Vec3 force = Vec3::Zero();      // as it enters f_int: minus the force the footing exerts
  Mat3 stiffness = Mat3::Zero();  // d force / d u
  double penetration = 0.0;       // g > 0 when touching
  double area = 0.0;              // A: the point's domain under the footprint (per radian)
  bool touching = false;
  bool on_base = false;  // false when touching through the side (eq. 13.5)
  /// Rough, on the base: the anchor the point sticks to from now on (eq. 13.4a).
  Vec3 stuck_at = Vec3::Zero();
};

/// The contact law: zero unless the point's domain reaches through the base (g > 0) and overlaps
/// the footprint (A > 0). `dim` 2 or 3; in axisymmetry x is the radius and A is per radian.
FootingContactForce footing_contact(const FootingPose& pose, const FootingContactPoint& point,
                                    const Vec3& u, int dim, bool axisymmetric);

/// One rigid footing of a phase: its geometry and motion, and the stick anchors of rough
/// contact (by point id), kept from step to step.
class RigidFooting {
 public:
  RigidFooting(const spec::RigidFooting& spec, int dim);

  const spec::RigidFooting& spec() const { return spec_; }
  const std::string& name() const { return spec_.name; }
  bool rough() const { return spec_.rough; }

  /// The displacement since the phase start reached at the end of [t0, t1], if the step
  /// starting from the last converged one converges.
  Vec3 displacement(double t0, double t1) const;
  /// The footing's pose for a displacement since the phase start.
  FootingPose pose(const Vec3& displacement) const;
  /// The displacement since the phase start at the last converged step.
  const Vec3& done() const { return done_; }

  /// Where point `id` sticks (rough), or nothing if it did not touch the base at the end of the
  /// last converged step.
  std::optional<Vec3> anchor(Index id) const;
  /// After a converged step: the displacement reached, and the points pressed against the base
  /// at its end with the anchors they used (the others lose theirs).
  void commit(const Vec3& displacement, std::unordered_map<Index, Vec3> touching);

  /// The state kept from step to step (displacement reached, anchors), for a checkpoint.
  void save(ByteWriter& out) const;
  void load(ByteReader& in);

 private:
  spec::RigidFooting spec_;
  int dim_;
  std::array<std::optional<Expression>, 3> components_;
  Vec3 done_ = Vec3::Zero();
  std::unordered_map<Index, Vec3> anchors_;
};

}  // namespace geompm
