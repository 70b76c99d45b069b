// Finite-strain kinematics at one integration point (docs/theory.md §3): from the incremental
// deformation gradient of the step to the Cauchy stress and the spatial tangent of the updated
// Lagrangian Newton step.
//
// Multiplicative elasto-plasticity with the exponential map (Simo 1992; de Souza Neto, Peric &
// Owen 2008, ch. 14): b_e^tr = dF b_e^n dF^T, eps_tr = 1/2 ln(b_e^tr), the material's update in
// log strain gives tau and D = d tau / d eps_tr, and the spatial tangent is (eq. 3.9)
//   a_ijkl = 1/(2J) [D : L : B]_ijkl - sigma_il delta_jk,
//   L = d ln(b_e^tr) / d b_e^tr,  B_ijkl = delta_ik b^tr_jl + delta_jk b^tr_il,
// so that the linearised internal virtual work is  int grad(du)_ij a_ijkl grad(Du)_kl dv. The
// last term is the initial-stress (geometric) part of the seed paper's eq. (10).
#pragma once

#include "geompm/core/tensor.hpp"
#include "geompm/materials/material.hpp"

namespace geompm {

struct FiniteStrainState {
  Mat3 deformation_gradient;       // F = dF F_n
  Mat3 elastic_left_cauchy_green;  // b_e after the return mapping
  Mat3 cauchy_stress;              // sigma = tau / J
  InternalVariables internal{};
  double jacobian = 1.0;  // J = det F
  // The return mapping moved the trial state back to the yield surface (the point flows
  // plastically in this iterate); false for an elastic update.
  bool plastic = false;
  // The material could not update the stress (StressUpdate::converged false): why
  // finite_strain_update returned false, if it did after reaching the material.
  bool stress_update_failed = false;
  // a above (only when requested), restricted to the requested components: entry (c, d) is
  // a_{ij kl} with (i, j) the c-th and (k, l) the d-th requested pair (all nine in natural
  // order by default).
  Tensor4 spatial_tangent;
};

/// Updates one point. Returns false if dF is not invertible with det > 0, or if the material's
/// update failed (`stress_update_failed`): the step is cut back.
/// `components` (pair indices 3i+j, `count` of them) limits the tangent to the components the
/// caller can use: five in 2D, where only xx, xy, yx, yy, zz of a gradient are non-zero.
bool finite_strain_update(const Material& material, const Mat3& dF, const Mat3& F_n,
                          const Mat3& be_n, const InternalVariables& internal_n, bool want_tangent,
                          FiniteStrainState& out, const int* components = nullptr, int count = 9);

}  // namespace geompm
