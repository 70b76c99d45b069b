#include "geompm/boundary/rigid_footing.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "geompm/boundary/grid_motions.hpp"
#include "geompm/core/byte_archive.hpp"
#include "geompm/core/error.hpp"

namespace geompm {

namespace {

/// The part of a point's domain under the footprint and its derivative with respect to the
/// point's horizontal position.
struct ContactArea {
  double area = 1.0;
  Vec3 d_area = Vec3::Zero();
};

// Contact area: the part of the domain under the footprint (eq. 13.2), and its derivative
// with respect to the point's horizontal position. Along each horizontal axis the overlap of
// (x - l, x + l) with (low, high) is min(x + l, high) - max(x - l, low): its ends move with x
// while they lie inside the footprint. Nothing when the domain misses the footprint.
std::optional<ContactArea> contact_area(const FootingPose& pose, const FootingContactPoint& point,
                                        const Vec3& x, int v, bool axisymmetric) {
  ContactArea a;
  double& area = a.area;
  Vec3& d_area = a.d_area;
  if (axisymmetric) {
    const double lo = std::max(x(0) - point.half(0), pose.low(0));
    const double hi = std::min(x(0) + point.half(0), pose.high(0));
    if (!(hi > lo)) return std::nullopt;
    area = 0.5 * (hi * hi - lo * lo);  // per radian: the integral of r dr
    d_area(0) = (x(0) + point.half(0) < pose.high(0) ? hi : 0.0) -
                (x(0) - point.half(0) > pose.low(0) ? lo : 0.0);
  } else {
    Vec3 overlap = Vec3::Ones(), d_overlap = Vec3::Zero();
    for (int t = 0; t < v; ++t) {
      const double lo = std::max(x(t) - point.half(t), pose.low(t));
      const double hi = std::min(x(t) + point.half(t), pose.high(t));
      if (!(hi > lo)) return std::nullopt;
      overlap(t) = hi - lo;
      d_overlap(t) = (x(t) + point.half(t) < pose.high(t) ? 1.0 : 0.0) -
                     (x(t) - point.half(t) > pose.low(t) ? 1.0 : 0.0);
    }
    for (int t = 0; t < v; ++t) area *= overlap(t);
    for (int t = 0; t < v; ++t) d_area(t) = d_overlap(t) * area / overlap(t);
  }
  return a;
}

/// The footing's side a domain is pushed out through: its horizontal axis (-1: none, the base
/// takes it), the overlap s past that edge and the sign of its outward normal.
struct SideExit {
  int side = -1;
  double through = 0.0;
  double sign = 0.0;
};

// The footing's side (eq. 13.5): a domain that reaches through the base by more than it
// reaches past the nearest edge (soil heaved beside the footing, drifting over its edge) is
// pushed out sideways through the side, by as much as it overlaps, instead of down by g. The
// force has the same size at the switch (kappa g o either way in 2D), and goes to zero with
// the overlap.
SideExit side_exit(const FootingPose& pose, const FootingContactPoint& point, const Vec3& x,
                   double g, int v, bool axisymmetric) {
  int side = -1;
  double through = g, sign = 0.0;
  for (int t = 0; t < v; ++t) {
    const double past_high = pose.high(t) - (x(t) - point.half(t));
    const double past_low = x(t) + point.half(t) - pose.low(t);
    // The axis is no side: a disc has none at r = 0.
    const bool low_is_side = !(axisymmetric && pose.low(t) <= 0.0);
    if (past_high < through) {
      side = t, through = past_high, sign = 1.0;
    }
    if (low_is_side && past_low < through) {
      side = t, through = past_low, sign = -1.0;
    }
  }
  return {side, through, sign};
}

// Side contact (eq. 13.5) and its derivatives: the force and stiffness of a point pushed out
// through the side `exit`.
void side_contact(const FootingPose& pose, const FootingContactPoint& point, const Vec3& x,
                  double g, const SideExit& exit, int v, bool axisymmetric,
                  FootingContactForce& c) {
  const double k = point.kappa;
  const int side = exit.side;
  const double through = exit.through, sign = exit.sign;
  // f = -sign kappa s g P on the side's normal axis: s the overlap past the edge (ds/dx =
  // -sign), g the height of the domain through the base, P the side's extent along the other
  // horizontal axis (1 in plane strain; the edge's radius per radian in axisymmetry).
  const double edge = sign > 0 ? pose.high(side) : pose.low(side);
  double P = 1.0;
  Vec3 dP = Vec3::Zero();
  if (axisymmetric) {
    P = edge;
  } else {
    for (int t = 0; t < v; ++t)
      if (t != side) {
        const double lo = std::max(x(t) - point.half(t), pose.low(t));
        const double hi = std::min(x(t) + point.half(t), pose.high(t));
        P = hi - lo;
        dP(t) = (x(t) + point.half(t) < pose.high(t) ? 1.0 : 0.0) -
                (x(t) - point.half(t) > pose.low(t) ? 1.0 : 0.0);
      }
  }
  c.area = g * P;
  c.force(side) = -sign * k * through * g * P;
  c.stiffness(side, side) = k * g * P;
  c.stiffness(side, v) = -sign * k * through * P;
  for (int t = 0; t < v; ++t)
    if (t != side) c.stiffness(side, t) = -sign * k * through * g * dP(t);
}

// Normal force kappa g A, pushing the point down (eq. 13.3), and its derivative (eq. 13.6).
void normal_penalty(double k, double g, const ContactArea& a, int v, FootingContactForce& c) {
  const double area = a.area;
  const Vec3& d_area = a.d_area;
  c.on_base = true;
  c.area = area;
  c.force(v) = k * g * area;
  c.stiffness(v, v) = k * area;
  for (int t = 0; t < v; ++t) c.stiffness(v, t) = k * g * d_area(t);
}

// Rough base, stick (eqs. 13.4, 13.4a) and its derivatives, added to the normal penalty's.
void rough_stick(const FootingPose& pose, const FootingContactPoint& point, const Vec3& x, double g,
                 const ContactArea& a, int v, FootingContactForce& c) {
  const double k = point.kappa;
  const double area = a.area;
  const Vec3& d_area = a.d_area;
  // Stick: the horizontal position relative to the footing held at the anchor (eq. 13.4). A
  // point that was below the base at the start of the step (g_0 < 0) first touches it where
  // its path through the step, straight from g_0 to g, meets the base: at the fraction
  // -g_0 / (g - g_0) of its motion relative to the footing. Only the rest of that motion
  // slips against the anchor, a share phi = g / (g - g_0) (eq. 13.4a), so the stick force
  // grows from zero as the point touches, instead of switching on with its whole motion of the
  // step, a jump in the residual that Newton cannot cross.
  double phi = 1.0, dphi_dg = 0.0;
  if (!point.anchored && point.start_gap < 0.0) {
    const double span = g - point.start_gap;
    phi = g > 0.0 ? g / span : 0.0;
    dphi_dg = g > 0.0 ? -point.start_gap / (span * span) : 0.0;
  }
  c.stuck_at = point.anchor;
  for (int t = 0; t < v; ++t) {
    const double motion = x(t) - pose.displacement(t) - point.anchor(t);
    const double slip = phi * motion;
    c.stuck_at(t) += motion - slip;
    c.force(t) = k * area * slip;
    c.stiffness(t, t) += k * area * phi;
    c.stiffness(t, v) += k * area * motion * dphi_dg;
    for (int s = 0; s < v; ++s) c.stiffness(t, s) += k * slip * d_area(s);
  }
}

}  // namespace

FootingContactForce footing_contact(const FootingPose& pose, const FootingContactPoint& point,
                                    const Vec3& u, int dim, bool axisymmetric) {
  FootingContactForce c;
  const int v = dim - 1;  // the vertical axis
  const Vec3 x = point.position + u;
  // Penetration of the point's domain through the base (eq. 13.1).
  const double g = x(v) + point.half(v) - pose.base;
  if (!(g > 0.0) && !point.bilateral) return c;
  const std::optional<ContactArea> area = contact_area(pose, point, x, v, axisymmetric);
  if (!area) return c;
  c.touching = true;
  c.penetration = g;
  const SideExit exit = side_exit(pose, point, x, g, v, axisymmetric);
  if (exit.side >= 0) {
    side_contact(pose, point, x, g, exit, v, axisymmetric, c);
    return c;
  }
  normal_penalty(point.kappa, g, *area, v, c);
  if (point.rough) rough_stick(pose, point, x, g, *area, v, c);
  return c;
}

RigidFooting::RigidFooting(const spec::RigidFooting& spec, int dim) : spec_(spec), dim_(dim) {
  for (int d = 0; d < dim; ++d)
    components_[d] = Expression(spec.components[d], component_place(spec.source, d));
}

Vec3 RigidFooting::displacement(double t0, double t1) const {
  Vec3 d = done_ + prescribed_increment(components_, spec_.velocity, t0, t1);
  for (int i = dim_; i < 3; ++i) d(i) = 0.0;
  return d;
}

FootingPose RigidFooting::pose(const Vec3& displacement) const {
  FootingPose pose;
  const int v = dim_ - 1;
  pose.displacement = displacement;
  pose.base = spec_.base + displacement(v);
  pose.low(0) = spec_.x[0] + displacement(0);
  pose.high(0) = spec_.x[1] + displacement(0);
  if (dim_ == 3) {
    pose.low(1) = spec_.y[0] + displacement(1);
    pose.high(1) = spec_.y[1] + displacement(1);
  }
  return pose;
}

std::optional<Vec3> RigidFooting::anchor(Index id) const {
  if (auto it = anchors_.find(id); it != anchors_.end()) return it->second;
  return std::nullopt;
}

void RigidFooting::commit(const Vec3& displacement, std::unordered_map<Index, Vec3> touching) {
  done_ = displacement;
  anchors_ = std::move(touching);
}

void RigidFooting::save(ByteWriter& out) const {
  out.put(done_);
  // Sorted by point id: the same state always gives the same bytes.
  std::vector<std::pair<Index, Vec3>> anchors(anchors_.begin(), anchors_.end());
  std::sort(anchors.begin(), anchors.end(),
            [](const auto& a, const auto& b) { return a.first < b.first; });
  out.put(anchors);
}

void RigidFooting::load(ByteReader& in) {
  in.get(done_);
  std::vector<std::pair<Index, Vec3>> anchors;
  in.get(anchors);
  anchors_ = std::unordered_map<Index, Vec3>(anchors.begin(), anchors.end());
}

}  // namespace geompm
