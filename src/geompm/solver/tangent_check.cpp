#include "geompm/solver/tangent_check.hpp"

#include <limits>

namespace geompm {

double directional_tangent_error(NonlinearProblem& problem, const Vector& x, const Vector& dx,
                                 const Vector& residual, double e) {
  Vector perturbed_residual;
  double force_scale = 0.0;
  if (!problem.evaluate(x + e * dx, perturbed_residual, force_scale, nullptr))
    return std::numeric_limits<double>::quiet_NaN();
  const double norm = residual.norm();
  return norm > 0.0 ? ((perturbed_residual - residual) / e + residual).norm() / norm : 0.0;
}

}  // namespace geompm
