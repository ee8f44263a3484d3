// The PD paper's contact model 2 (eqs 23-25, Fig 1): bonds across the interface between points of
// different bodies, with the force-stretch law of a bulk bond that softens instead of snapping.
// A pair's stretch is s = r / L - 1, L its contact distance (pd/laws/contact_pair.hpp: the
// distance at which the short-range repulsion would start). Its force density on i, per unit volume
// of j,
//   compression (s < 0):   f = c |s|, pushing apart                                    (eq 25)
//   tension, bonded:       f = c s up to the yield stretch s_y, then
//                          f = c s_y exp(-m (s - s_y)), pulling together              (eq 24)
// with c = 18 K / (pi delta^4) the bulk bond's micromodulus (Silling and Askari 2005), the c of
// eq 23. The paper leaves the bond's life to "certain criteria"; ours (docs/pd.md, "Contact model
// 2"):
//  - a pair bonds when it is compressed (s < 0): the surfaces touched;
//  - a bond remembers its largest stretch s_max; pulled back from the softening branch it unloads
//    along the secant to the origin, f = s f(s_max) / s_max (the damage stays: what softening
//    took is dissipated, as in cohesive-zone models, e.g. Camacho and Ortiz, Int. J. Solids
//    Struct. 33 (1996) 2899);
//  - it breaks once its force has decayed to kBreakFraction of the peak c s_y: at the break
//    stretch s_y + ln(1 / kBreakFraction) / m;
//  - a broken pair re-forms, as new, when it is compressed again.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "pd/laws/contact_pair.hpp"

namespace coldspray::pd {

// A bond breaks when its softened force has fallen to this fraction of its peak.
inline constexpr double kBreakFraction = 0.01;

// The largest stretch of a pair that is not bonded (never compressed, or broken since).
inline constexpr double kUnbonded = -1.0;

struct InterfaceBondLaw {
  double yield_stretch = 0.0;  // s_y
  double softening = 0.0;      // m
  // s_y + ln(1 / kBreakFraction) / m.
  double break_stretch() const;
};

// The bulk's critical stretch from its fracture energy by eq 23, G_c = pi c s_c^2 delta^5 / 10
// with c = 18 K / (pi delta^4): s_c = sqrt(5 G_c / (9 K delta)). G_c in J/m^2, K in Pa, delta m.
double critical_stretch(double fracture_energy, double bulk_modulus, double delta);

// The pair's largest stretch after a step that left it at stretch s, from `largest` before:
// bonds form under compression, remember their largest stretch and break past the break stretch.
double next_largest_stretch(const InterfaceBondLaw& law, double stretch, double largest);

// The force density f / c at stretch s of a pair whose largest stretch is `largest` (kUnbonded
// or >= 0): positive pushes the points apart, negative pulls them together; unbonded pairs pull
// with nothing.
double force_per_micromodulus(const InterfaceBondLaw& law, double stretch, double largest);

// The law's tension envelope f(s) / c for s >= 0: c s, then eq 24, and zero past the break.
double envelope_per_micromodulus(const InterfaceBondLaw& law, double stretch);

// Model 2 as a contact law, with rest length L the repulsion's contact distance and micromodulus
// c = 18 K / (pi delta^4), N/m^6. The contact list keeps each candidate's largest stretch
// (ContactList::remembers_stretch); a pair is held while its bond has formed and not broken.
struct InterfaceBonds {
  static constexpr std::string_view kName = "interface-bonds";
  static constexpr bool kAdhesive = true;  // whether holds() can be true
  double reach = 0.0;                      // L (1 + the break stretch), m: every bond breaks before
  ContactDistance rest;
  InterfaceBondLaw bond;
  double micromodulus = 0.0;  // N/m^6

  // s_c from the interface's fracture energy by eq 23, and s_y and m, unless the case gives them,
  // from the fit of eq 24 to the bulk-fracture test (pd/laws/bulk_fracture.hpp); throws InputError
  // at contact.peridynamics.fracture_energy when neither it nor both surface energies are given.
  static InterfaceBonds make(const ContactLawInputs& in);

  double stretch(const ContactPair& p, double length) const { return length / rest.of(p) - 1.0; }
  // Eqs 24-25: c f(s) V_j along the pair, with the bond's largest stretch, N/m^3.
  Eigen::Vector3d force(const ContactPair& p, const Eigen::Vector3d& r, double length) const {
    const double f =
        force_per_micromodulus(bond, stretch(p, length), p.list.largest_stretch[p.candidate]);
    return micromodulus * f * p.N.volume[p.j] / length * r;
  }
  bool holds(const ContactPair& p) const { return p.list.largest_stretch[p.candidate] >= 0.0; }
};

}  // namespace coldspray::pd
