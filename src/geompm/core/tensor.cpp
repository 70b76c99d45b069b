#include "geompm/core/tensor.hpp"

#include <cassert>

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

Tensor4 eigen_derivative4(const Mat3& q, const Mat3& theta) {
  // D_ijkl = sum_ab theta_ab Q_ia Q_jb (Q_ka Q_lb + Q_kb Q_la) / 2   (symmetric in kl).
  // theta is symmetric (divided differences), so the (a, b) and (b, a) terms pair up into
  // 2 theta_ab s_ab s_ab^T with s_ab = sym(q_a q_b^T): six symmetric rank-one terms instead of
  // nine, formed as one product S W S^T (S: 9 x 6, W diagonal). The kernel's hottest function.
  assert((theta - theta.transpose()).cwiseAbs().maxCoeff() <=
         1e-12 * std::max(1.0, theta.cwiseAbs().maxCoeff()));
  Eigen::Matrix<double, 9, 6> S;
  Eigen::Matrix<double, 6, 1> w;
  int k = 0;
  for (int a = 0; a < 3; ++a)
    for (int b = a; b < 3; ++b, ++k) {
      const Mat3 mab = q.col(a) * q.col(b).transpose();
      S.col(k) = flatten(0.5 * (mab + mab.transpose()));
      w(k) = a == b ? theta(a, a) : 2.0 * theta(a, b);
    }
  return S * w.asDiagonal() * S.transpose();
}

Tensor4 principal_function_derivative4(const SymmetricEigen& eps, const Vec3& tau,
                                       const Mat3& dtau_deps) {
  const Vec3& x = eps.values;
  const Mat3& c = dtau_deps;
  const double scale = std::max(1.0, x.cwiseAbs().maxCoeff());
  Mat3 spin = Mat3::Zero();  // the a = b terms come from c below, not from eq. 3.6
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) {
      if (a == b) continue;
      const double d = x(a) - x(b);
      spin(a, b) = std::abs(d) <= 1e-8 * scale ? 0.5 * (c(a, a) - c(a, b) - c(b, a) + c(b, b))
                                               : (tau(a) - tau(b)) / d;
    }
  Tensor4 d = eigen_derivative4(eps.vectors, spin);
  for (int a = 0; a < 3; ++a) {
    const Vec9 ma = flatten(eps.vectors.col(a) * eps.vectors.col(a).transpose());
    for (int b = 0; b < 3; ++b) {
      const Vec9 mb = flatten(eps.vectors.col(b) * eps.vectors.col(b).transpose());
      d.noalias() += c(a, b) * ma * mb.transpose();
    }
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
