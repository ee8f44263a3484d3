// The numerical bulk-fracture test behind contact model 2's constants (PD paper, "Contact Model 2"
// and Fig 1): a bulk of the lattice's bonds, each breaking irreversibly at the critical stretch
// s_c (eq 23), is stretched along z until every bond crossing a plane has broken, and the force
// the two parts exert on each other is recorded against the stretch. We stretch it affinely (every
// bond xi becomes (xi_x, xi_y, (1 + e) xi_z)), so the curve is the lattice's own, free of where a
// crack would localise: the traction is the sum over the bonds crossing a plane, a bond of
// vertical extent k spacings crossing k planes,
//   sigma(e) ~ sum over unbroken bonds of c s(xi, e) k (1 + e) xi_z / |xi'|,
// and is reported as the force of one equivalent bond, f / c = sigma(e) / sigma'(0): slope 1, as
// eq 24's linear branch. Bonds break where s = s_c, the steepest first, so the force peaks at
// e = s_c and decays as the flatter ones follow (in the continuum limit as s_c (s_c / e)^(3/2)).
//
// The fit of eq 24 to it (docs/pd.md, "Contact model 2"): s_y at the curve's peak, and m so that
// the interface bond's work to its break, c (s_y^2 / 2 + (1 - kBreakFraction) s_y / m), equals the
// bulk curve's: the interface keeps the bulk's strength and its work of fracture per bond.
// Everything is in units of s_c: the lattice (simple cubic, horizon = horizon_factor spacings)
// fixes the curve's shape, so s_y = a s_c and m = b / s_c.
#pragma once

#include <vector>

#include "pd/laws/interface_bonds.hpp"

namespace coldspray::pd {

// Samples per s_c of the curve the solver fits: the peak's stretch is found to 1e-3 s_c.
inline constexpr int kBulkFractureSamples = 1000;

struct ForceStretchCurve {
  std::vector<double> stretch;  // e / s_c
  std::vector<double> force;    // f / (c s_c)
};

// The bulk curve from e = 0 to the last bond's break, `samples` points per s_c.
ForceStretchCurve bulk_fracture_curve(double horizon_factor, int samples);

// The area under a curve in its units, by the trapezoidal rule.
double work_of_fracture(const ForceStretchCurve& curve);

// eq 24 fitted to the curve (in units of s_c: yield_stretch / s_c and softening * s_c).
InterfaceBondLaw fit_interface_law(const ForceStretchCurve& curve);

// The fitted law at critical stretch s_c: s_y = a s_c, m = b / s_c from the fit in units of s_c.
InterfaceBondLaw scaled_law(const InterfaceBondLaw& fit_in_units_of_s_c, double s_c);

// The law's work to its break, c (s_y^2 / 2 + (1 - kBreakFraction) s_y / m), per c.
double interface_work(const InterfaceBondLaw& law);

}  // namespace coldspray::pd
