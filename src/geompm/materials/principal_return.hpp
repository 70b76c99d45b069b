// The return mapping in principal stress space shared by the elastic-perfectly plastic soil
// models whose yield surface is made of planes (Tresca, Mohr-Coulomb, tension cut-off).
//
// For an isotropic material the Kirchhoff stress, the elastic strain and the plastic flow share
// the principal axes of the trial strain (de Souza Neto, Peric & Owen 2008, "dSPO", §8.1), so the
// return is solved on three principal values sorted tau_1 >= tau_2 >= tau_3 (tension positive).
// With planar yield functions, a constant elasticity and no hardening, the return to any face of
// the surface (a plane, an edge where two planes meet, a vertex where three meet) is the solution
// of a small linear system, and so is its tangent: the mapping is exact, with no iteration
// (docs/materials.md eqs. M.1-M.7). Which face is the right one is decided by the Kuhn-Tucker
// conditions (eq. M.5), trying the faces a model lists, in its order.
#pragma once

#include <span>
#include <vector>

#include "geompm/core/tensor.hpp"
#include "geompm/materials/material.hpp"

namespace geompm {

/// One plane of a yield surface in principal stress space, f(tau) = normal . tau - limit <= 0,
/// and the direction of the plastic strain it produces, d eps_p = d gamma * flow (eq. M.2-M.3).
struct YieldPlane {
  Vec3 normal;
  Vec3 flow;
  double limit = 0;
};

/// Kuhn-Tucker conditions are checked to this fraction of the largest stress in play: far above
/// the round-off of the linear solves, far below any stress that matters.
inline constexpr double kkt_tolerance = 1e-9;

/// A surface has at most this many planes (Mohr-Coulomb with its tension cut-off has six).
inline constexpr int max_yield_planes = 8;

/// The result of a principal return: stresses and tangent in the order of the trial strains.
struct PrincipalReturn {
  Vec3 stress = Vec3::Zero();          // tau_a
  Vec3 plastic_strain = Vec3::Zero();  // increment of the principal plastic strains
  Mat3 tangent = Mat3::Zero();         // C_ab = d tau_a / d eps_trial_b
  unsigned active = 0;                 // bit k set: plane k is active; 0: elastic
  // False if an iterative return (hyperbolic_return.hpp) did not converge: the stress is then
  // not a solution of the return, and the caller must not use it (the step is cut back).
  bool converged = true;
};

/// The principal values of a symmetric matrix in descending order (tau_1 >= tau_2 >= tau_3 for
/// a stress), with the eigenvectors as the columns in the same order.
SymmetricEigen principal_descending(const Mat3& a);

/// Isotropic elasticity on principal values: tau_a = lambda sum_b eps_b + 2 mu eps_a (eq. M.1).
Mat3 principal_elasticity(double lambda, double mu);

/// Every set of one, two or three of `plane_count` planes, as bit masks, smallest sets first
/// (planes before edges before vertices), in plane order within a size.
std::vector<unsigned> active_sets_up_to_three(int plane_count);

/// Which one-sided derivative the return reports for a trial state on the surface (no plane
/// violated, some within the Kuhn-Tucker tolerance), where the update is not differentiable:
/// the elastic side's, D^e, or the plastic side's, eq. M.6 on the face of the planes at the
/// surface (docs/materials.md §1.7).
enum class SurfaceTangent { elastic, plastic };

/// The side a point reports on the surface: `chosen` (the model's `surface_tangent`), except that
/// a point that has never yielded (equivalent plastic strain zero) reports the elastic side's
/// (docs/materials.md §1.7): the plastic side is meant for the last steps' plastic zone, and at
/// a stress-free point of cohesionless soil - at the apex, where every plane is at the surface -
/// it would report a zero tangent.
inline SurfaceTangent surface_side(SurfaceTangent chosen, double equivalent_plastic_strain) {
  return equivalent_plastic_strain > 0.0 ? chosen : SurfaceTangent::elastic;
}

/// The return to the yield planes (at most max_yield_planes) of principal trial strains sorted
/// eps_1 >= eps_2 >= eps_3.
/// Elastic when no plane is violated; otherwise the first set of `candidates` whose return
/// satisfies the Kuhn-Tucker conditions (eq. M.5) is taken. Should none do (it does not happen for
/// the surfaces of this room, but a tolerance is involved) the candidate that violates them least
/// is taken, so the update always returns.
PrincipalReturn return_to_yield_planes(const Vec3& trial_strain, const Mat3& elasticity,
                                       std::span<const YieldPlane> planes,
                                       std::span<const unsigned> candidates,
                                       SurfaceTangent on_surface = SurfaceTangent::elastic);

/// The equivalent plastic strain of a principal plastic strain increment, sqrt(2/3 de_p : de_p)
/// (eq. M.8): the von Mises measure, which for an isochoric (Tresca) flow is the usual one.
double equivalent_plastic_strain(const Vec3& plastic_strain_increment);

/// Writes the Kirchhoff stress, the elastic strain and the tangent D = d tau / d eps_trial
/// (eq. M.7) of a plastic return into `out` (not the internal variables).
void assemble_principal_update(const SymmetricEigen& trial, const PrincipalReturn& r,
                               StressUpdate& out);

}  // namespace geompm
