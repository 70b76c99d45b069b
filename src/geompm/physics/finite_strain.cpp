#include "geompm/physics/finite_strain.hpp"

#include <Eigen/LU>
#include <cmath>

namespace geompm {

bool finite_strain_update(const Material& material, const Mat3& dF, const Mat3& F_n,
                          const Mat3& be_n, const InternalVariables& internal_n, bool want_tangent,
                          FiniteStrainState& out, const int* components, int count) {
  out.stress_update_failed = false;
  const double dJ = dF.determinant();
  if (!(dJ > 0.0) || !std::isfinite(dJ)) return false;

  out.deformation_gradient = dF * F_n;
  out.jacobian = out.deformation_gradient.determinant();
  const Mat3 be_trial = dF * be_n * dF.transpose();

  // eps_tr = 1/2 ln(b_e^tr): one spectral decomposition serves the strain and L.
  const SymmetricEigen e = symmetric_eigen(be_trial);
  if (!(e.values.minCoeff() > 0.0)) return false;
  const auto log_fn = [](double x) { return std::log(x); };
  const Mat3 trial_strain = 0.5 * isotropic_function(e, log_fn);

  StressUpdate update;
  material.update(trial_strain, internal_n, update);
  if (!update.converged) {
    out.stress_update_failed = true;
    return false;
  }
  out.cauchy_stress = update.kirchhoff / out.jacobian;
  out.internal = update.internal;
  out.plastic = !(update.elastic_strain == trial_strain);
  // An elastic update keeps the trial strain: b_e is the trial one, no second decomposition.
  out.elastic_left_cauchy_green =
      update.elastic_strain == trial_strain ? be_trial : symmetric_exp(2.0 * update.elastic_strain);

  if (want_tangent) {
    static constexpr int all[9] = {0, 1, 2, 3, 4, 5, 6, 7, 8};
    const int* comps = components ? components : all;
    const Tensor4 L = isotropic_function_derivative(e, log_fn, [](double x) { return 1.0 / x; });
    // Rows of D and columns of B for the requested components only (eq. 3.9):
    // a_sub = 1/(2J) D[c, :] L B[:, d] - sigma_il delta_jk.
    using Rows = Eigen::Matrix<double, Eigen::Dynamic, 9, Eigen::RowMajor, 9, 9>;
    using Cols = Eigen::Matrix<double, 9, Eigen::Dynamic, Eigen::ColMajor, 9, 9>;
    Rows D_rows(count, 9);
    Cols B_cols(9, count);
    for (int c = 0; c < count; ++c) {
      D_rows.row(c) = update.tangent.row(comps[c]);
      const int k = comps[c] / 3, l = comps[c] % 3;
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j)
          B_cols(pair_index(i, j), c) =
              (i == k ? be_trial(j, l) : 0.0) + (j == k ? be_trial(i, l) : 0.0);
    }
    const Rows DL = D_rows.lazyProduct(L);
    out.spatial_tangent.topLeftCorner(count, count) = (0.5 / out.jacobian) * DL.lazyProduct(B_cols);
    for (int c = 0; c < count; ++c)
      for (int d = 0; d < count; ++d) {
        const int i = comps[c] / 3, j = comps[c] % 3, k = comps[d] / 3, l = comps[d] % 3;
        if (j == k) out.spatial_tangent(c, d) -= out.cauchy_stress(i, l);
      }
  }
  return true;
}

}  // namespace geompm
