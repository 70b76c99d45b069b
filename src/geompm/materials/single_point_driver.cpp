#include "geompm/materials/single_point_driver.hpp"

#include <fmt/format.h>

#include <Eigen/QR>
#include <algorithm>

#include "geompm/core/error.hpp"

namespace geompm {

namespace {

constexpr std::array<std::array<int, 2>, 6> component_index = {
    {{0, 0}, {1, 1}, {2, 2}, {0, 1}, {1, 2}, {2, 0}}};

Mat3 from_components(const Vec6& v) {
  Mat3 a;
  for (int c = 0; c < 6; ++c) {
    const auto [i, j] = component_index[c];
    a(i, j) = a(j, i) = v(c);
  }
  return a;
}

// d tau_p / d eps_q for components p, q: a shear strain component moves eps_ij and eps_ji
// together, so its column is the sum of the two columns of the Tensor4.
double component_tangent(const Tensor4& d, int p, int q) {
  const auto [i, j] = component_index[p];
  const auto [k, l] = component_index[q];
  const double v = d(pair_index(i, j), pair_index(k, l));
  return k == l ? v : v + d(pair_index(i, j), pair_index(l, k));
}

}  // namespace

Vec6 to_components(const Mat3& a) {
  Vec6 v;
  for (int c = 0; c < 6; ++c) v(c) = a(component_index[c][0], component_index[c][1]);
  return v;
}

SinglePointDriver::SinglePointDriver(const Material& material, const InternalVariables& internal)
    : material_(material) {
  state_.internal = internal;
  evaluate(Mat3::Zero(), state_);
}

void SinglePointDriver::evaluate(const Mat3& strain_increment, DriverState& out) const {
  StressUpdate u;
  material_.update(state_.elastic_strain + strain_increment, state_.internal, u);
  if (!u.converged)
    throw RunError(
        fmt::format("single-point driver: the material's stress update (its return "
                    "mapping) did not converge, at a trial strain of norm {:g}",
                    (state_.elastic_strain + strain_increment).norm()));
  out.strain = state_.strain + strain_increment;
  out.elastic_strain = u.elastic_strain;
  out.stress = u.kirchhoff;
  out.internal = u.internal;
  out.tangent = u.tangent;
}

std::vector<DriverState> SinglePointDriver::follow(const PathSegment& segment) {
  std::vector<int> free;  // the stress-controlled components
  for (int c = 0; c < 6; ++c)
    if (segment.control[c] == Control::stress) free.push_back(c);
  const int n_free = static_cast<int>(free.size());
  const Vec6 start_stress = to_components(state_.stress);

  std::vector<DriverState> history;
  Vec6 increment = Vec6::Zero();  // the free components keep the last increment as a guess
  for (int step = 1; step <= segment.increments; ++step) {
    const double s = static_cast<double>(step) / segment.increments;
    for (int c = 0; c < 6; ++c)
      if (segment.control[c] == Control::strain)
        increment(c) = segment.strain_increment(c) / segment.increments;
    Vec6 target = start_stress + s * (segment.final_stress - start_stress);

    DriverState next;
    evaluate(from_components(increment), next);
    int iteration = 0;
    for (;; ++iteration) {
      // Newton on the free strains: r = tau_free - target, J = d tau_free / d eps_free.
      const Vec6 stress = to_components(next.stress);
      Eigen::VectorXd r(n_free);
      double scale = 0;
      for (int a = 0; a < n_free; ++a) {
        r(a) = stress(free[a]) - target(free[a]);
        scale = std::max({scale, std::abs(stress(free[a])), std::abs(target(free[a]))});
      }
      scale =
          std::max({scale, stress.cwiseAbs().maxCoeff(), 1e-12 * material_.reference_modulus()});
      if (n_free == 0 || r.cwiseAbs().maxCoeff() <= tolerance * scale) break;
      if (iteration == max_iterations)
        throw RunError(
            fmt::format("single-point driver: no convergence in {} iterations "
                        "(increment {} of {}, residual {:g})",
                        max_iterations, step, segment.increments, r.cwiseAbs().maxCoeff()));
      Eigen::MatrixXd jacobian(n_free, n_free);
      for (int a = 0; a < n_free; ++a)
        for (int b = 0; b < n_free; ++b)
          jacobian(a, b) = component_tangent(next.tangent, free[a], free[b]);
      // At an edge or the apex of a perfectly plastic surface the stresses do not fix every free
      // strain (in triaxial compression on the edge tau_1 = tau_2 only eps_1 + eps_2 is fixed:
      // the flow may be shared between the two planes in any proportion), so J is singular. The
      // minimum-norm correction leaves the undetermined combination as it was: symmetric paths
      // stay symmetric. A target the material cannot reach shows as a residual that does not fall.
      Eigen::CompleteOrthogonalDecomposition<Eigen::MatrixXd> solver(jacobian);
      solver.setThreshold(1e-10);
      const Eigen::VectorXd delta = solver.solve(-r);
      for (int a = 0; a < n_free; ++a) increment(free[a]) += delta(a);
      evaluate(from_components(increment), next);
    }
    next.iterations = iteration;
    state_ = next;
    history.push_back(state_);
  }
  return history;
}

}  // namespace geompm
