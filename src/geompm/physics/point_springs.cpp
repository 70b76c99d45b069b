#include "geompm/physics/point_springs.hpp"

#include <cmath>

namespace geompm {

namespace {
std::vector<char> driven(const std::vector<double>& stiffness) {
  std::vector<char> acts(stiffness.size(), 0);
  for (std::size_t p = 0; p < stiffness.size(); ++p) acts[p] = stiffness[p] > 0.0;
  return acts;
}
}  // namespace

PointSprings::PointSprings(const GridSystem& grid, const MaterialPoints& points,
                           PointTargets targets)
    : PointForces("prescribed point motion", grid, points, driven(targets.stiffness),
                  [this](Index p, const Vec3& u, Vec3& force, Mat3& stiffness) {
                    spring(p, u, force, stiffness);
                  }),
      targets_(std::move(targets)),
      reaction_(points.size(), Vec3::Zero()) {}

void PointSprings::spring(Index p, const Vec3& u, Vec3& force, Mat3& stiffness) {
  const double k = targets_.stiffness[p];
  force.setZero();
  stiffness.setZero();
  Vec3 reaction = Vec3::Zero();
  for (int i = 0; i < grid_.dim(); ++i) {
    if (!(targets_.mask[p] >> i & 1u)) continue;
    force(i) = k * (u(i) - targets_.target[p](i));
    stiffness(i, i) = k;
    reaction(i) = -force(i);
  }
  reaction_[p] = reaction;  // each point by one thread only
}

double PointSprings::driving_force_scale() const {
  double sum = 0.0;
  for (std::size_t p = 0; p < targets_.stiffness.size(); ++p)
    for (int i = 0; i < grid_.dim(); ++i)
      if (targets_.mask[p] >> i & 1u) {
        const double f = targets_.stiffness[p] / spring_ratio * targets_.target[p](i);
        sum += f * f;
      }
  return std::sqrt(sum);
}

void PointSprings::report(const Vector& /*du*/, Reactions& reactions) {
  for (const int set : targets_.sets) {
    Vec3 force = Vec3::Zero();
    for (Index p = 0; p < points_.size(); ++p)
      if (points_.sets[p] >> set & 1u) force += reaction_[p];
    reactions.point_sets.try_emplace(set, Vec3::Zero()).first->second += force;
  }
}

}  // namespace geompm
