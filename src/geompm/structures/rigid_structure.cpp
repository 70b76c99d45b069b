#include "geompm/structures/rigid_structure.hpp"

#include <Eigen/Geometry>

#include "geompm/core/byte_archive.hpp"
#include "geompm/structures/structure_drive.hpp"

namespace geompm {

Mat3 rotation_matrix(const Vec3& theta) {
  const double angle = theta.norm();
  if (angle == 0.0) return Mat3::Identity();
  return Eigen::AngleAxisd(angle, theta / angle).toRotationMatrix();
}

RigidStructure::RigidStructure(std::string name, StructureMesh mesh, double density,
                               std::optional<Vec3> reference_point)
    : Structure(std::move(name), std::move(mesh)),
      components_(rigid_body_components(this->mesh().kinematics())),
      body_(mass_properties(this->mesh(), density)),
      velocity_(Vector::Zero(components_)),
      acceleration_(Vector::Zero(components_)) {
  reference_ = reference_point.value_or(body_.centroid);
  initial_reference_ = phase_reference_ = reference_;
}

int RigidStructure::add_unknowns(DofMap& dofs) const {
  return dofs.add_field(field_name(), FieldKind::Other, 1, components_);
}

Index RigidStructure::dof(const DofMap& dofs, int k) const {
  return dofs.dof(dofs.find(field_name()), 0, k);
}

void RigidStructure::displacement_weights(const DofMap& dofs, const Vec3& x, Index /*cell*/,
                                          std::vector<DofWeight>& out) const {
  // u(x) = t + theta x d, d = x - c (eq. 17.1): e_i for the translations, e_j x d for the
  // rotations.
  out.clear();
  const int field = dofs.find(field_name());
  const Vec3 d = x - reference_;
  if (kinematics() == Kinematics::Axisymmetric) {
    out.push_back({dofs.dof(field, 0, 1), Vec3::UnitY()});
    return;
  }
  const int dim = mesh().dim();
  for (int i = 0; i < dim; ++i) out.push_back({dofs.dof(field, 0, i), Vec3::Unit(i)});
  if (dim == 2) {
    out.push_back({dofs.dof(field, 0, 2), Vec3(-d.y(), d.x(), 0.0)});
    return;
  }
  for (int j = 0; j < 3; ++j) out.push_back({dofs.dof(field, 0, 3 + j), Vec3::Unit(j).cross(d)});
}

void RigidStructure::split(const Vector& q, Vec3& t, Vec3& theta) const {
  if (components_ == 6) {
    t = q.head<3>();
    theta = q.tail<3>();
  } else {
    t = Vec3(q(0), q(1), 0.0);
    theta = Vec3(0.0, 0.0, q(2));
  }
}

void RigidStructure::commit(const DofMap& dofs, const Vector& du) {
  Vector q(components_);
  for (int k = 0; k < components_; ++k) q(k) = du(dof(dofs, k));
  Vec3 t, theta;
  split(q, t, theta);
  // The exact pose (eq. 17.3): x' = c + t + R (x - c), with R = exp(theta) the rotation whose
  // infinitesimal form the step used.
  const Mat3 R = rotation_matrix(theta);
  std::vector<Vec3> nodes = mesh().nodes();
  for (Vec3& x : nodes) x = reference_ + t + R * (x - reference_);
  move_nodes(std::move(nodes));
  body_.centroid = reference_ + t + R * (body_.centroid - reference_);
  reference_ += t;
  rotation_ = R * rotation_;
  angle_ += theta.z();
}

void RigidStructure::start_phase() {
  phase_reference_ = reference_;
  phase_rotation_ = rotation_;
  phase_angle_ = angle_;
}

namespace {
Vec3 rotation_vector(const Mat3& R) {
  const Eigen::AngleAxisd a(R);
  return a.angle() * a.axis();
}
}  // namespace

Vec3 RigidStructure::rotation() const {
  return components_ == 3 ? Vec3(0, 0, angle_) : rotation_vector(rotation_);
}

Vec3 RigidStructure::phase_rotation() const {
  return components_ == 3 ? Vec3(0, 0, angle_ - phase_angle_)
                          : rotation_vector(rotation_ * phase_rotation_.transpose());
}

Eigen::MatrixXd RigidStructure::mass_matrix() const {
  const double m = body_.mass;
  const Vec3 s = body_.centroid - reference_;
  const Mat3 J = inertia_about({m, body_.centroid, inertia()}, reference_);
  Eigen::MatrixXd M = Eigen::MatrixXd::Zero(components_, components_);
  if (components_ == 3) {
    // The kinetic energy 1/2 m |v + omega e_z x s|^2 + 1/2 J_cm omega^2.
    M(0, 0) = M(1, 1) = m;
    M(0, 2) = M(2, 0) = -m * s.y();
    M(1, 2) = M(2, 1) = m * s.x();
    M(2, 2) = J(2, 2);
    return M;
  }
  Mat3 skew;  // [s]x: [s]x a = s x a
  skew << 0, -s.z(), s.y(), s.z(), 0, -s.x(), -s.y(), s.x(), 0;
  M.topLeftCorner<3, 3>() = m * Mat3::Identity();
  M.topRightCorner<3, 3>() = -m * skew;  // v . (omega x s) = -v . [s]x omega
  M.bottomLeftCorner<3, 3>() = m * skew;
  M.bottomRightCorner<3, 3>() = J;
  return M;
}

Vector RigidStructure::generalised_force(const Vec3& force, const Vec3& moment) const {
  // The virtual work F . (t + theta x s) + M . theta: F on t, s x F + M on theta.
  const Vec3 total = moment + (body_.centroid - reference_).cross(force);
  Vector f(components_);
  if (components_ == 3) {
    f << force.x(), force.y(), total.z();
  } else {
    f << force, total;
  }
  return f;
}

void RigidStructure::set_rates(Vector velocity, Vector acceleration) {
  velocity_ = std::move(velocity);
  acceleration_ = std::move(acceleration);
}

void RigidStructure::save(ByteWriter& out) const {
  out.put(mesh().nodes());
  out.put(body_.centroid);
  out.put(reference_);
  out.put(phase_reference_);
  out.put(rotation_);
  out.put(phase_rotation_);
  out.put(angle_);
  out.put(phase_angle_);
  out.put(std::vector<double>(velocity_.begin(), velocity_.end()));
  out.put(std::vector<double>(acceleration_.begin(), acceleration_.end()));
}

void RigidStructure::load(ByteReader& in) {
  restore_nodes(in.get<std::vector<Vec3>>());
  in.get(body_.centroid);
  in.get(reference_);
  in.get(phase_reference_);
  in.get(rotation_);
  in.get(phase_rotation_);
  in.get(angle_);
  in.get(phase_angle_);
  const auto v = in.get<std::vector<double>>(), a = in.get<std::vector<double>>();
  velocity_ = Eigen::Map<const Vector>(v.data(), static_cast<Index>(v.size()));
  acceleration_ = Eigen::Map<const Vector>(a.data(), static_cast<Index>(a.size()));
}

}  // namespace geompm
