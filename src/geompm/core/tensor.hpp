// Fourth-order tensors as 9x9 matrices (entry (3i+j, 3k+l) holds T_ijkl) and the functions of
// symmetric tensors that finite-strain kinematics needs: the logarithm and exponential, and the
// derivative of an isotropic tensor function (Daleckii-Krein formula, docs/theory.md eq. 3.6).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>

#include "geompm/core/types.hpp"

namespace geompm {

using Tensor4 = Eigen::Matrix<double, 9, 9>;
using Vec9 = Eigen::Matrix<double, 9, 1>;

inline int pair_index(int i, int j) { return 3 * i + j; }

/// The 9-vector of a 3x3 matrix, row-major (entry 3i+j holds A_ij).
inline Vec9 flatten(const Mat3& a) {
  Vec9 v;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) v(3 * i + j) = a(i, j);
  return v;
}
inline Mat3 unflatten(const Vec9& v) {
  Mat3 a;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) a(i, j) = v(3 * i + j);
  return a;
}

/// Symmetric fourth-order identity: I_ijkl = (d_ik d_jl + d_il d_jk) / 2.
Tensor4 symmetric_identity4();
/// I (x) I: d_ij d_kl.
Tensor4 identity_dyad_identity4();
/// Isotropic elasticity: lambda I(x)I + 2 mu I_sym.
Tensor4 isotropic_elasticity4(double lambda, double mu);

/// Spectral decomposition of a symmetric matrix: a = Q diag(values) Q^T.
struct SymmetricEigen {
  Vec3 values;
  Mat3 vectors;  // columns are the eigenvectors
};
SymmetricEigen symmetric_eigen(const Mat3& a);

/// f(A) = Q diag(f(values)) Q^T for symmetric A.
template <class F>
Mat3 isotropic_function(const SymmetricEigen& e, F&& f) {
  const Vec3 fv(f(e.values(0)), f(e.values(1)), f(e.values(2)));
  return e.vectors * fv.asDiagonal() * e.vectors.transpose();
}

/// Divided differences of f over the eigenvalues x: Theta_ab = (f(x_a) - f(x_b)) / (x_a - x_b),
/// and f'(x_a) where two eigenvalues coincide (to a relative 1e-8), the limit of the former.
template <class F, class DF>
Mat3 divided_differences(const Vec3& x, F&& f, DF&& df) {
  Mat3 theta;
  const double scale = std::max(1.0, x.cwiseAbs().maxCoeff());
  for (int a = 0; a < 3; ++a)
    for (int b = a; b < 3; ++b) {
      const double d = x(a) - x(b);
      theta(a, b) = theta(b, a) =
          std::abs(d) <= 1e-8 * scale ? df(0.5 * (x(a) + x(b))) : (f(x(a)) - f(x(b))) / d;
    }
  return theta;
}

/// The Tensor4 of eq. 3.6 from the eigenvectors (columns of q) and the divided differences.
Tensor4 eigen_derivative4(const Mat3& q, const Mat3& theta);

/// Derivative d f(A) / dA of an isotropic tensor function of a symmetric A, as a Tensor4 acting
/// on symmetric increments: Q (Theta o (Q^T dA Q)) Q^T (Daleckii-Krein, docs/theory.md eq. 3.6).
/// Valid for repeated eigenvalues (the limit is taken, not avoided).
template <class F, class DF>
Tensor4 isotropic_function_derivative(const SymmetricEigen& e, F&& f, DF&& df) {
  return eigen_derivative4(e.vectors, divided_differences(e.values, f, df));
}

/// Derivative of a tensor function given by its principal values, tau = sum_a tau_a m_a with
/// m_a = q_a (x) q_a, where each tau_a may depend on all three principal values eps_b of the
/// argument (a return mapping in principal stresses, docs/materials.md eq. M.7):
///   D = sum_ab C_ab m_a (x) m_b + sum_{a != b} Theta_ab (spin terms of eq. 3.6),
///   C_ab = d tau_a / d eps_b,   Theta_ab = (tau_a - tau_b) / (eps_a - eps_b).
/// Where eps_a and eps_b coincide (to the relative 1e-8 of divided_differences) Theta_ab takes
/// its limit (C_aa - C_ab - C_ba + C_bb) / 2, valid because an isotropic function has
/// tau_a = tau_b there. For tau_a = f(eps_a) this is isotropic_function_derivative.
Tensor4 principal_function_derivative4(const SymmetricEigen& eps, const Vec3& tau,
                                       const Mat3& dtau_deps);

/// Matrix logarithm and exponential of a symmetric matrix (positive definite for the log).
Mat3 symmetric_log(const Mat3& a);
Mat3 symmetric_exp(const Mat3& a);

}  // namespace geompm
