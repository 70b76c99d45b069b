#include "geompm/physics/finite_strain.hpp"

#include <Eigen/LU>
#include <cmath>

namespace geompm {

bool finite_strain_update(const Material& material, const Mat3& dF, const Mat3& F_n,
                          const Mat3& be_n, const InternalVariables& internal_n, bool want_tangent,
                          FiniteStrainState& out) {
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
  out.cauchy_stress = update.kirchhoff / out.jacobian;
  out.internal = update.internal;
  // An elastic update keeps the trial strain: b_e is the trial one, no second decomposition.
  out.elastic_left_cauchy_green =
      update.elastic_strain == trial_strain ? be_trial : symmetric_exp(2.0 * update.elastic_strain);

  if (want_tangent) {
    const Tensor4 L = isotropic_function_derivative(e, log_fn, [](double x) { return 1.0 / x; });
    Tensor4 B = Tensor4::Zero();
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int k = 0; k < 3; ++k)
          for (int l = 0; l < 3; ++l)
            B(pair_index(i, j), pair_index(k, l)) =
                (i == k ? be_trial(j, l) : 0.0) + (j == k ? be_trial(i, l) : 0.0);
    // lazyProduct: coefficient-based 9x9 products, without the packing of Eigen's blocked GEMM.
    const Tensor4 LB = L.lazyProduct(B);
    out.spatial_tangent = (0.5 / out.jacobian) * update.tangent.lazyProduct(LB);
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        for (int l = 0; l < 3; ++l)
          out.spatial_tangent(pair_index(i, j), pair_index(j, l)) -= out.cauchy_stress(i, l);
  }
  return true;
}

}  // namespace geompm
