// How far an impacting body has pushed into what it hit: its centroid's travel along its initial
// velocity since its first contact, over its size along that direction, and the largest value,
// reached where the impact's compression ends. It decides whether bonds may form (docs/bonding.md,
// "Activation"): for a sphere pressing into a plastic half-space the energy balance
// 1/2 m v^2 = integral of p_m pi a^2 d(delta), with a^2 = 2 R delta (Johnson, Contact Mechanics,
// 1985, §11.4), gives delta / d proportional to v sqrt(rho / p_m), so a critical penetration is a
// critical ratio of kinetic energy density to flow stress, the mechanical term of the critical
// velocity of Assadi et al. (Acta Mater 51 (2003) 4379) and Schmidt et al. (Acta Mater 54 (2006)
// 729, Eq 8), with the flow stress at the impact's own rates and temperatures. A centroid's
// travel converges with the grid, where quantities at the interface do not
// (docs/validation/critical-velocity.md).
#pragma once

#include <array>

namespace coldspray::bodies {

struct Bodies;

struct Penetration {
  std::array<double, 3> direction{};  // unit initial velocity; zeros: the body started at rest
  double size = 0.0;            // extent of the body along `direction` at t = 0, plus a spacing, m
  double first_contact = -1.0;  // time of the step in which the body first touched another, s;
                                // < 0: not yet
  double start = 0.0;           // centroid . direction when that step began, m
  double last = 0.0;            // centroid . direction after the last step, m
  double largest = 0.0;         // the largest (centroid . direction - start) / size so far
  double peak = -1.0;           // time the centroid first stopped advancing after the first
                                // contact (the compression's end), s; < 0: not yet
};

// Sets each body's direction, size and last centroid from its points at t = 0.
void start_penetration(Bodies& s);

// After a step (its contact impulses in s.contact_impulse): a body that touched another for the
// first time starts its count from where its centroid stood before the step; every body in
// contact since updates its largest penetration, and marks its peak the first time its centroid
// does not advance. A serial sum in point order: the same bits on any number of threads.
void track_penetration(Bodies& s);

// Whether bodies a and b may bond: once the impact that brought them together has penetrated
// `critical` (until then the contact between them is the unbonded one, whatever the bond law's
// D_bond). That impact is the one of the body whose first contact came later (the one that
// arrived), or, when they touched first in the same step, of the one that penetrated further (a
// particle, not the substrate it starts on). critical <= 0: always, the thesis' model.
bool pair_activated(const Penetration& a, const Penetration& b, double critical);

}  // namespace coldspray::bodies
