#include "geompm/core/tensor.hpp"

#include <Eigen/Eigenvalues>
#include <cmath>

namespace geompm {

Tensor4 symmetric_identity4() {
  Tensor4 t = Tensor4::Zero();
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      t(pair_index(i, j), pair_index(i, j)) += 0.5;
      t(pair_index(i, j), pair_index(j, i)) += 0.5;
    }
  return t;
}

Tensor4 identity_dyad_identity4() {
  Tensor4 t = Tensor4::Zero();
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) t(pair_index(i, i), pair_index(k, k)) = 1.0;
  return t;
}

Tensor4 isotropic_elasticity4(double lambda, double mu) {
  return lambda * identity_dyad_identity4() + 2.0 * mu * symmetric_identity4();
}

SymmetricEigen symmetric_eigen(const Mat3& a) {
  // The iterative solver is accurate also for nearly repeated eigenvalues, where the direct
  // (closed-form) one loses the orthogonality of the vectors.
  Eigen::SelfAdjointEigenSolver<Mat3> solver(a);
  return {solver.eigenvalues(), solver.eigenvectors()};
}

Mat3 isotropic_function(const SymmetricEigen& e, const std::function<double(double)>& f) {
  Vec3 fv(f(e.values(0)), f(e.values(1)), f(e.values(2)));
  return e.vectors * fv.asDiagonal() * e.vectors.transpose();
}

Tensor4 isotropic_function_derivative(const SymmetricEigen& e,
                                      const std::function<double(double)>& f,
                                      const std::function<double(double)>& df) {
  // Divided differences; eigenvalues closer than a relative 1e-8 count as equal, where the
  // divided difference tends to the derivative (the formula stays exact in the limit).
  Mat3 theta;
  const double scale = std::max(1.0, e.values.cwiseAbs().maxCoeff());
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const double xa = e.values(a), xb = e.values(b);
      if (std::abs(xa - xb) <= 1e-8 * scale)
        theta(a, b) = df(0.5 * (xa + xb));
      else
        theta(a, b) = (f(xa) - f(xb)) / (xa - xb);
    }
  // D_ijkl = sum_ab theta_ab Q_ia Q_jb (Q_ka Q_lb + Q_kb Q_la) / 2   (symmetric in kl)
  const Mat3& q = e.vectors;
  Tensor4 d = Tensor4::Zero();
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      const Vec3 qa = q.col(a), qb = q.col(b);
      const Mat3 mab = qa * qb.transpose();
      const Mat3 sym = 0.5 * (mab + mab.transpose());
      d += theta(a, b) * flatten(mab) * flatten(sym).transpose();
    }
  return d;
}

Mat3 symmetric_log(const Mat3& a) {
  return isotropic_function(symmetric_eigen(a), [](double x) { return std::log(x); });
}

Mat3 symmetric_exp(const Mat3& a) {
  return isotropic_function(symmetric_eigen(a), [](double x) { return std::exp(x); });
}

}  // namespace geompm
