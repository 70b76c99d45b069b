#include "geompm/boundary/footing_contact.hpp"

#include "geompm/physics/gimp_weights.hpp"

namespace geompm {

std::vector<Vec3> domain_top_offsets(const MaterialPoints& points, int dim) {
  // The footing touches a point at the top of its domain: the image of the seeded domain's top
  // under the point's F (eq. 13.1), carried by the step's deformation within the step.
  std::vector<Vec3> offset(points.size(), Vec3::Zero());
  for (Index p = 0; p < points.size(); ++p) {
    offset[p] = points.domain_deformation(p, dim) * points.initial_top_offset[p];
    for (int i = dim; i < 3; ++i) offset[p](i) = 0.0;
  }
  return offset;
}

FootingContact::FootingContact(const GridSystem& grid, const MaterialPoints& points,
                               const DofMap& dofs, FootingContactInputs inputs)
    : FootingContact(grid, points, dofs, *inputs.footings, prepare(grid, points, inputs)) {}

FootingContact::FootingContact(const GridSystem& grid, const MaterialPoints& points,
                               const DofMap& dofs, std::vector<RigidFooting>& footings,
                               Prepared prepared)
    : PointForces("rigid footings", grid, points, dofs, std::move(prepared.acts),
                  std::move(prepared.offset),
                  [this](Index p, const Vec3& u, Vec3& f, Mat3& K) { law(p, u, f, K); }),
      footings_(footings),
      step_(std::move(prepared.step)) {}

FootingContact::Prepared FootingContact::prepare(const GridSystem& grid,
                                                 const MaterialPoints& points,
                                                 const FootingContactInputs& inputs) {
  const Index n = points.size();
  const int dim = grid.dim(), v = dim - 1;
  Prepared out;
  out.acts.assign(n, 0);
  out.offset = domain_top_offsets(points, dim);
  Step& step = out.step;
  for (std::size_t k = 0; k < inputs.footings->size(); ++k) {
    const RigidFooting& footing = (*inputs.footings)[k];
    const Vec3 d = footing.displacement(inputs.t0, inputs.t1);
    const FootingPose pose = footing.pose(d);
    std::vector<std::pair<Index, FootingContactPoint>> candidates;
    std::vector<int> slot(n, -1);
    for (Index p = 0; p < n; ++p) {
      if (!inputs.acts_on_body[k][points.body[p]]) continue;
      // Its horizontal extent: the cpGIMP half-lengths (eq. 9.4) at the start of the step.
      Vec3 half = particle_half_lengths(points.initial_half_size[p],
                                        points.domain_deformation(p, dim), dim);
      half(v) = 0.0;
      const Vec3 top = points.position[p] + out.offset[p];
      // A point may touch the base in this step if its domain, grown by a cell, reaches it.
      const double reach = grid.cell_size(p);
      bool near = top(v) > pose.base - reach;
      for (int t = 0; t < v; ++t)
        near = near && top(t) + half(t) > pose.low(t) - reach &&
               top(t) - half(t) < pose.high(t) + reach;
      if (!near) continue;
      FootingContactPoint c;
      c.position = top;
      c.half = half;
      // kappa = factor x E / h by default (eq. 13.7): the point's stiffness over its cell size.
      c.kappa = footing.spec().penalty.value_or(footing.spec().penalty_factor * inputs.modulus[p] /
                                                reach);
      c.rough = footing.rough();
      // A point pressed against the base at the end of the last step stays in contact in both
      // directions through this step's iterations (eq. 13.8). A rough one sticks where it was
      // first touched: where its path met the base in the step of its first contact (eq. 13.4a),
      // from its position and gap at the start of that step.
      const auto anchor = footing.anchor(points.id[p]);
      c.bilateral = anchor.has_value();
      c.anchored = anchor.has_value();
      c.anchor = anchor ? *anchor : Vec3(top - footing.done());
      c.anchor(v) = 0.0;
      c.start_gap = top(v) - footing.pose(footing.done()).base;
      slot[p] = static_cast<int>(candidates.size());
      candidates.emplace_back(p, c);
      out.acts[p] = 1;
    }
    std::vector<char> held;
    for (const auto& candidate : candidates) held.push_back(candidate.second.bilateral);
    step.pressed.emplace_back(candidates.size(), 0);
    step.hold.emplace_back(std::move(held));
    step.displacement.push_back(d);
    step.pose.push_back(pose);
    step.points.push_back(std::move(candidates));
    step.slot.push_back(std::move(slot));
  }
  return out;
}

void FootingContact::law(Index p, const Vec3& u, Vec3& force, Mat3& stiffness) {
  force.setZero();
  stiffness.setZero();
  for (std::size_t k = 0; k < step_.pose.size(); ++k)
    if (const int at = step_.slot[k][p]; at >= 0) {
      const FootingContactForce c = footing_contact(step_.pose[k], step_.points[k][at].second, u,
                                                    grid_.dim(), grid_.axisymmetric());
      step_.pressed[k][at] = c.on_base && c.penetration > 0.0;
      force += c.force;
      stiffness += c.stiffness;
    }
}

void FootingContact::hold(bool restart) {
  // After an accepted Newton iterate, or before a new solve of the step: the points the contact
  // law holds in both directions (ContactHold, docs/theory.md §13). At the iterate a newly held
  // point touches, so the residual Newton has there does not change.
  for (std::size_t k = 0; k < step_.points.size(); ++k) {
    ContactHold& hold = step_.hold[k];
    if (restart)
      hold.restart();
    else
      hold.accept(step_.pressed[k]);
    for (std::size_t at = 0; at < hold.size(); ++at)
      step_.points[k][at].second.bilateral = hold.held(at);
  }
}

void FootingContact::report(const Vector& du, Reactions& reactions) {
  // At the converged increment (before the points move): the force each footing exerts on the
  // soil, and the points touching it, which keep (or take) their anchors.
  step_.touching.assign(footings_.size(), {});
  for (std::size_t k = 0; k < footings_.size(); ++k) {
    Vec3 force = Vec3::Zero();
    for (const auto& [p, point] : step_.points[k]) {
      const Vec3 u = place_displacement(p, du);
      const FootingContactForce c =
          footing_contact(step_.pose[k], point, u, grid_.dim(), grid_.axisymmetric());
      force -= c.force;
      if (c.on_base && c.penetration > 0.0) step_.touching[k][points_.id[p]] = c.stuck_at;
    }
    reactions.structures.try_emplace(footings_[k].name(), Vec3::Zero()).first->second += force;
  }
}

void FootingContact::commit() {
  for (std::size_t k = 0; k < footings_.size(); ++k)
    footings_[k].commit(step_.displacement[k], std::move(step_.touching[k]));
}

}  // namespace geompm
