// The contact conditions of one contact segment as equations that Newton can solve
// (docs/theory.md §18): the Karush-Kuhn-Tucker conditions of the normal contact (no penetration,
// no tension, a pressure only where touching) and the tangential law (smooth; rough, i.e. bonded;
// adhesion-limited; Coulomb friction with an optional cap), each written as a semi-smooth
// complementarity function (Alart & Curnier 1991). Their roots are exactly the conditions, so the
// scale c that makes the multipliers lengths changes the path of the iterations, never the result.
//
// The unknowns of a segment are its multipliers in length units, l_n and l_t: the contact
// pressure is c l_n and the shear c l_t. Its kinematics are the mean penetration p (> 0: the
// structure is inside the soil) and the mean slip s (the structure's tangential displacement
// relative to the soil's) over the segment, both linear in the step's displacements.
#pragma once

#include <limits>

namespace geompm {

enum class TangentialContact { Smooth, Rough, Adhesion, Friction };

/// What the contact allows along its surface.
struct ContactLaw {
  TangentialContact tangential = TangentialContact::Smooth;
  double adhesion = 0.0;  // Adhesion: the largest shear stress, a pressure, or ...
  double alpha = 0.0;     // ... this fraction of the soil's s_u where it touches (per segment)
  double friction = 0.0;  // Friction: Coulomb's mu
  double cap = std::numeric_limits<double>::infinity();  // Friction: the largest shear stress
};

enum class ContactState { Open, Stick, Slip };

/// The residuals of a segment's two equations (length units) and their derivatives with respect
/// to (p, s, l_n, l_t). The normal equation is p = 0 where the segment touches (l_n + p > 0) and
/// l_n = 0 where it is open; the tangential one is s = 0 where it sticks and l_t = +-b (the
/// shear bound over c) where it slips, l_t = 0 where open or smooth.
struct ContactEquations {
  double normal = 0.0, tangential = 0.0;
  double normal_d[4] = {0, 0, 0, 0};
  double tangential_d[4] = {0, 0, 0, 0};
  ContactState state = ContactState::Open;
};

/// The equations at (p, s, l_n, l_t); `scale` is c (pressure per unit length), which converts the
/// law's stresses into the multipliers' length units. A segment counts as touching where
/// l_n + p > -closed: a structure placed on the soil's surface (p = 0 up to round-off) starts in
/// contact rather than free, whose tangent would be singular under a prescribed load.
ContactEquations contact_equations(const ContactLaw& law, double scale, double p, double s,
                                   double l_n, double l_t, double closed = 0.0);

/// The two tangential equations of a segment in 3D, where the shear is a vector (eq. 18.7a):
/// it sticks while |l_t + s| <= b (s = 0) and slips along the trial direction,
/// l_t = b (l_t + s) / |l_t + s|, so that the shear's size is the bound whichever way the
/// structure slides. Derivatives with respect to (p, s_0, s_1, l_n, l_t0, l_t1). Only where the
/// bound is finite (adhesion, friction) and the segment touches; otherwise, each tangent on its
/// own (contact_equations) is the same law.
struct TangentialPair {
  double residual[2] = {0.0, 0.0};
  double d[2][6] = {{0, 0, 0, 0, 0, 0}, {0, 0, 0, 0, 0, 0}};
  ContactState state = ContactState::Stick;
};

TangentialPair tangential_pair(const ContactLaw& law, double scale, double p, const double s[2],
                               double l_n, const double l_t[2]);

}  // namespace geompm
