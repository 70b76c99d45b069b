#include "geompm/structures/deformable_structure_term.hpp"

#include <Eigen/Geometry>
#include <Eigen/LU>

#include "geompm/mesh/cell_geometry.hpp"
#include "geompm/mesh/element.hpp"
#include "geompm/physics/gauss_cell.hpp"

namespace geompm {

namespace {

// The Gauss points of one cell (physics/gauss_cell.hpp) with the structure's material and the
// states its Gauss points carry.
template <class E>
bool integrate_cell(const DeformableStructure& s, Index c,
                    const Eigen::Matrix<double, E::nodes, E::dim>& X,
                    const Eigen::Matrix<double, E::nodes, E::dim>& du, bool want_tangent,
                    PointKernelResult<E>& cell, GaussPointState* states) {
  const GaussPointState* start = s.gauss_points().data() + c * E::quadrature_size();
  return integrate_gauss_cell<E>(
      X, du, s.kinematics() == Kinematics::Axisymmetric, want_tangent, false,
      [&](int q) {
        return PointStartState{&s.material(), Vec3::Zero(), 0.0,
                               start[q].F,    start[q].be,  start[q].internal};
      },
      cell,
      [&](int q, const PointKernelResult<E>& r) {
        if (states)
          states[q] = {r.state.deformation_gradient, r.state.elastic_left_cauchy_green,
                       r.state.internal, r.state.cauchy_stress};
      });
}

}  // namespace

DeformableStructureTerm::DeformableStructureTerm(DeformableStructure& structure, const DofMap& dofs,
                                                 const Vec3& gravity, Vector load,
                                                 std::optional<Newmark> newmark, double dt)
    : structure_(structure), dofs_(dofs), applied_(std::move(load)), newmark_(newmark), dt_(dt) {
  const Mesh& mesh = structure.mesh().mesh();
  const int dim = structure.dim();
  const int field = dofs.find(structure.field_name());
  cell_size_ = nodes_per_cell(mesh.cell_type) * dim;
  for (Index c = 0; c < mesh.num_cells(); ++c)
    for (Index a : mesh.cell_nodes(c))
      for (int i = 0; i < dim; ++i) cell_dofs_.push_back(dofs.dof(field, a, i));
  // Self-weight, f_a = sum_q m_q N_a(xi_q) g (eq. 17.13), and the consistent mass matrix (eq.
  // 17.14), both from the Gauss points' constant masses: the same in every configuration.
  if (applied_.size() == 0) applied_ = Vector::Zero(structure.num_nodes() * dim);
  dispatch_cell_type(mesh.cell_type, [&](auto element) {
    using E = decltype(element);
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const auto nodes = mesh.cell_nodes(c);
      Eigen::MatrixXd M = Eigen::MatrixXd::Zero(E::nodes, E::nodes);
      for (int q = 0; q < E::quadrature_size(); ++q) {
        const double m = structure.gauss_mass()[c * E::quadrature_size() + q];
        const typename E::Values N = E::shape(E::quadrature_point(q));
        M += m * N * N.transpose();
        for (int a = 0; a < E::nodes; ++a)
          for (int i = 0; i < dim; ++i) applied_(nodes[a] * dim + i) += m * N(a) * gravity(i);
      }
      if (newmark_) cell_mass_.push_back(std::move(M));
    }
  });
}

void DeformableStructureTerm::declare_couplings(SparsityBuilder& pattern) const {
  std::vector<Index> block(cell_size_);
  for (std::size_t c = 0; c * cell_size_ < cell_dofs_.size(); ++c) {
    std::copy_n(cell_dofs_.begin() + c * cell_size_, cell_size_, block.begin());
    pattern.couple_unknowns(block);
  }
}

bool DeformableStructureTerm::add_cells(const Vector& du, SystemForces* forces,
                                        SparseMatrix* tangent,
                                        std::vector<GaussPointState>* states) const {
  const StructureMesh& structure_mesh = structure_.mesh();
  const Mesh& mesh = structure_mesh.mesh();
  if (states) states->resize(structure_.gauss_points().size());
  return dispatch_cell_type(mesh.cell_type, [&](auto element) {
    using E = decltype(element);
    constexpr int n = E::nodes * E::dim;
    Eigen::Matrix<double, E::nodes, E::dim> X, u;
    PointKernelResult<E> cell;
    for (Index c = 0; c < mesh.num_cells(); ++c) {
      const auto nodes = mesh.cell_nodes(c);
      const Index* dofs = cell_dofs_.data() + c * n;
      for (int a = 0; a < E::nodes; ++a)
        for (int i = 0; i < E::dim; ++i) {
          X(a, i) = mesh.nodes[nodes[a]](i);
          u(a, i) = du(dofs[a * E::dim + i]);
        }
      GaussPointState* out = states ? states->data() + c * E::quadrature_size() : nullptr;
      if (!integrate_cell<E>(structure_, c, X, u, tangent != nullptr, cell, out)) return false;
      scatter_cell<E>(cell, dofs, dofs_, forces ? &forces->internal : nullptr, tangent);
    }
    return true;
  });
}

void DeformableStructureTerm::add_inertia(const Vector& u, SystemForces& forces,
                                          SparseMatrix* tangent) const {
  // M a with Newmark's acceleration of the nodes (seed eq. 8), M / (beta dt^2) on the tangent;
  // M acts on each component alike.
  const Vector a =
      newmark_->inertial_acceleration(u, structure_.velocity(), structure_.acceleration());
  const int dim = structure_.dim();
  const Mesh& mesh = structure_.mesh().mesh();
  for (Index c = 0; c < mesh.num_cells(); ++c) {
    const auto nodes = mesh.cell_nodes(c);
    const Eigen::MatrixXd& M = cell_mass_[c];
    const Index* dofs = cell_dofs_.data() + c * cell_size_;
    for (Index p = 0; p < M.rows(); ++p)
      for (Index q = 0; q < M.cols(); ++q)
        for (int i = 0; i < dim; ++i) {
          forces.inertia(dofs[p * dim + i]) += M(p, q) * a(nodes[q] * dim + i);
          if (tangent)
            add_to_tangent(*tangent, dofs_, dofs[p * dim + i], dofs[q * dim + i],
                           newmark_->mass_factor() * M(p, q));
        }
  }
}

bool DeformableStructureTerm::add(const Vector& du, SystemForces& forces, SparseMatrix* tangent) {
  if (!add_cells(du, &forces, tangent, nullptr)) return false;
  const int field = dofs_.find(structure_.field_name());
  const Index offset = dofs_.field(field).offset;
  forces.external.segment(offset, applied_.size()) += applied_;
  if (newmark_) add_inertia(structure_.nodal(dofs_, du), forces, tangent);
  return true;
}

bool DeformableStructureTerm::states_at(const Vector& du,
                                        std::vector<GaussPointState>& states) const {
  return add_cells(du, nullptr, nullptr, &states);
}

void DeformableStructureTerm::report(const Vector& du, Reactions& /*reactions*/) {
  converged_ = du;
  reported_ = true;
}

void DeformableStructureTerm::commit() {
  if (!reported_) return;
  std::vector<GaussPointState> states;
  if (!states_at(converged_, states))
    throw std::logic_error("deformable structure: a converged increment is inadmissible");
  structure_.set_gauss_points(std::move(states));
  const Vector u = structure_.nodal(dofs_, converged_);
  if (newmark_) {
    Vector a = newmark_->acceleration(u, structure_.velocity(), structure_.acceleration());
    Vector v = newmark_->velocity(structure_.velocity(), structure_.acceleration(), a);
    structure_.set_rates(std::move(v), std::move(a));
  } else {
    structure_.set_rates(u / dt_, Vector::Zero(u.size()));
  }
  structure_.commit(dofs_, converged_);
}

DriveForces drive_forces(const DeformableStructure& structure, const StructureDrive& drive,
                         const DofMap& dofs, const Vector& reaction, double t) {
  const Vector load = drive.nodal_load(t, structure.num_nodes());
  const int dim = structure.dim();
  DriveForces f;
  for (Index a = 0; a < structure.num_nodes(); ++a) {
    Vec3 force = Vec3::Zero();
    for (int i = 0; i < dim; ++i) {
      const Index d = structure.dof(dofs, a, i);
      force(i) = dofs.constrained(d) ? reaction(d) : load(a * dim + i);
    }
    if (structure.kinematics() == Kinematics::Axisymmetric) force.x() = 0.0;
    f.force += force;
    f.moment += structure.mesh().nodes()[a].cross(force);
  }
  if (structure.kinematics() == Kinematics::Axisymmetric) f.moment.setZero();
  return f;
}

}  // namespace geompm
