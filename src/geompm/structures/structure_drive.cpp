#include "geompm/structures/structure_drive.hpp"

#include <fmt/format.h>

#include <limits>

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
      const Expression& f = *motion_[k];
      du[k] = velocity_ ? 0.5 * (t1 - t0) * (f.at_time(t0) + f.at_time(t1))
                        : f.at_time(t1) - f.at_time(t0);
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

}  // namespace geompm
