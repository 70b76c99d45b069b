#include "geompm/structures/structure_drive.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "geompm/structures/node_selection.hpp"

#include "geompm/core/error.hpp"

namespace geompm {

int rigid_body_components(Kinematics kinematics) {
  return kinematics == Kinematics::ThreeD ? 6 : 3;
}

int drive_component(Kinematics kinematics, int k) {
  if (kinematics == Kinematics::ThreeD) return k;
  return k < 2 ? k : 5;  // ux, uy, rotation about z
}

StructureDrive::StructureDrive(Kinematics kinematics)
    : kinematics_(kinematics),
      motion_(rigid_body_components(kinematics)),
      load_(rigid_body_components(kinematics)) {}

StructureDrive::StructureDrive(const spec::StructureDrive& drive, Kinematics kinematics)
    : StructureDrive(kinematics) {
  velocity_ = drive.velocity;
  for (int k = 0; k < components(); ++k) {
    const int c = drive_component(kinematics, k);
    const std::string where = fmt::format("{} (its {} {})", drive.source.describe(),
                                          c < 3 ? "translation" : "rotation", "xyz"[c % 3]);
    if (!drive.motion[c].empty()) motion_[k] = Expression(drive.motion[c], where);
    if (!drive.load[c].empty()) load_[k] = Expression(drive.load[c], where);
  }
}

bool StructureDrive::prescribed(int k) const {
  // Axisymmetry: only the axial translation (k = 1) may move.
  return (kinematics_ == Kinematics::Axisymmetric && k != 1) || motion_[k].has_value();
}

std::vector<double> StructureDrive::increment(double t0, double t1) const {
  std::vector<double> du(components(), std::numeric_limits<double>::quiet_NaN());
  for (int k = 0; k < components(); ++k) {
    if (kinematics_ == Kinematics::Axisymmetric && k != 1) {
      du[k] = 0.0;
    } else if (motion_[k]) {
      du[k] = increment_of(*motion_[k], velocity_, t0, t1);
    }
  }
  return du;
}

std::vector<double> StructureDrive::load(double t) const {
  std::vector<double> f(components(), 0.0);
  for (int k = 0; k < components(); ++k)
    if (load_[k] && !(kinematics_ == Kinematics::Axisymmetric && k != 1))
      f[k] = load_[k]->at_time(t);
  return f;
}

double StructureDrive::increment_of(const Expression& f, bool velocity, double t0,
                                    double t1) const {
  return velocity ? 0.5 * (t1 - t0) * (f.at_time(t0) + f.at_time(t1))
                  : f.at_time(t1) - f.at_time(t0);
}

StructureDrive::StructureDrive(const std::vector<const spec::StructureDrive*>& drives,
                               const StructureMesh& mesh)
    : kinematics_(mesh.kinematics()), nodal_(true), dim_(mesh.dim()) {
  for (const spec::StructureDrive* d : drives) {
    NodeSet set;
    set.nodes = select_nodes(mesh, d->nodes.value_or(spec::StructureNodes{}));
    set.velocity = d->velocity;
    for (int i = 0; i < dim_; ++i) {
      if (!d->motion[i].empty()) set.motion[i] = Expression(d->motion[i]);
      if (!d->load[i].empty()) set.load[i] = Expression(d->load[i]);
    }
    sets_.push_back(std::move(set));
  }
  if (kinematics_ == Kinematics::Axisymmetric) {
    // The nodes on the axis (r = 0 within round-off of the mesh's size) cannot move radially.
    double size = 0.0;
    for (const Vec3& x : mesh.nodes()) size = std::max(size, std::abs(x.x()));
    for (Index a = 0; a < static_cast<Index>(mesh.nodes().size()); ++a)
      if (std::abs(mesh.nodes()[a].x()) <= 1e-9 * size) axis_nodes_.push_back(a);
  }
}

std::vector<DriveConstraint> StructureDrive::constraints(double t0, double t1) const {
  std::vector<DriveConstraint> out;
  if (!nodal_) {
    const std::vector<double> du = increment(t0, t1);
    for (int k = 0; k < components(); ++k)
      if (!std::isnan(du[k])) out.push_back({0, k, du[k]});
    return out;
  }
  // Node by node and component, the last set that prescribes it wins.
  std::map<std::pair<Index, int>, double> prescribed;
  for (Index a : axis_nodes_) prescribed[{a, 0}] = 0.0;
  for (const NodeSet& set : sets_)
    for (int i = 0; i < dim_; ++i)
      if (set.motion[i]) {
        const double du = increment_of(*set.motion[i], set.velocity, t0, t1);
        for (Index a : set.nodes) prescribed[{a, i}] = du;
      }
  for (const auto& [at, du] : prescribed) out.push_back({at.first, at.second, du});
  return out;
}

Vector StructureDrive::nodal_load(double t, Index num_nodes) const {
  // A set's force is its total, shared equally by its nodes.
  Vector f = Vector::Zero(num_nodes * dim_);
  for (const NodeSet& set : sets_)
    for (int i = 0; i < dim_; ++i)
      if (set.load[i]) {
        const double share = set.load[i]->at_time(t) / static_cast<double>(set.nodes.size());
        for (Index a : set.nodes) f(a * dim_ + i) += share;
      }
  return f;
}

}  // namespace geompm
