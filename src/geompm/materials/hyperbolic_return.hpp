// The return mapping in principal stresses to the smooth hyperbolic Mohr-Coulomb surface
// (hyperbolic_surface.hpp; docs/materials.md §3.6): one smooth surface, so no faces to choose
// between, but curved, so the return is solved by Newton's method (eq. M.22) and its tangent is
// the derivative of the converged solution (eq. M.23).
#pragma once

#include "geompm/materials/hyperbolic_surface.hpp"
#include "geompm/materials/principal_return.hpp"

namespace geompm {

/// The return of principal trial strains sorted eps_1 >= eps_2 >= eps_3 to the surface `yield`
/// with flow from `potential` (both of the form of hyperbolic_surface.hpp). Elastic when
/// F(tau_tr) <= 0; `active` is 1 for a plastic return. The stresses keep the trial strains' order.
/// `converged` is false if neither Newton's method nor the continuation reached the solution
/// (a non-finite trial state, say): the result must then not be used.
PrincipalReturn return_to_hyperbolic_surface(const Vec3& trial_strain, const Mat3& elasticity,
                                             const HyperbolicSurface& yield,
                                             const HyperbolicSurface& potential,
                                             SurfaceTangent on_surface = SurfaceTangent::elastic);

}  // namespace geompm
