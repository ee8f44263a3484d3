// The debonding law of a bond (docs/bonding.md, "Debonding"; `bonding.debond`): the extrinsic
// cohesive law of Camacho and Ortiz (IJSS 33, 1996), rigid until the traction across the bond
// reaches its strength sigma_c, then softening linearly with the opening delta to zero at
// delta_c = 2 G_c / sigma_c, so that a bond opened to the end has taken its fracture energy G_c;
// mixed mode through Ortiz and Pandolfi's effective traction and opening (IJNME 44, 1999, eqs
// 9-12), with beta the shear strength over the tensile strength. Damage d = delta / delta_c never
// heals. A bonded point's strength and energy are its full bond's times min(D_bond, 1): the
// thesis' bonding parameter read as the share of the interface that bonded (§6.2, "D_bond
// instead defines the amount of contact pressure converted to bond strength"), so that a point
// barely bonded is weaker than one deep in the bonded zone. SI units.
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <optional>

#include "case/case.hpp"

namespace coldspray::bonding {

struct CohesiveLaw {
  bool enabled = false;            // debond.law: cohesive
  std::optional<double> strength;  // the full bond's sigma_c, Pa; unset: the point's flow stress
  double fracture_energy = 0.0;    // the full bond's G_c, J/m^2
  double shear_ratio = 1.0;        // beta

  static CohesiveLaw from_case(const case_file::Bonding& b);
  // A bonded point's full-bond strength: the law's, or the point's flow stress.
  double full_strength(double flow_stress) const { return strength ? *strength : flow_stress; }
};

// The share of its full bond a point with bonding parameter D_bond holds: min(D_bond, 1).
inline double bonded_share(double bond) { return std::min(bond, 1.0); }

// Ortiz-Pandolfi's effective traction of a traction t on a surface of unit normal n (n pointing
// from the body t acts on to the other, so t . n > 0 is tension): sqrt(<t_n>^2 + |t_s|^2 / b^2),
// a compressive normal part not counting.
double effective_traction(const Eigen::Vector3d& t, const Eigen::Vector3d& n, double beta);

// Their effective opening of a relative displacement u (the other body's minus this one's):
// sqrt(<u_n>^2 + b^2 |u_s|^2).
double effective_opening(const Eigen::Vector3d& u, const Eigen::Vector3d& n, double beta);

// The effective traction a bond of strength sigma_c carries at damage d: sigma_c (1 - d).
inline double traction_capacity(double strength, double damage) {
  return strength * std::max(0.0, 1.0 - damage);
}

// The damage an effective opening increment adds: d(delta) / delta_c, delta_c = 2 G_c / sigma_c.
inline double damage_increment(double opening, double strength, double fracture_energy) {
  return opening * strength / (2.0 * fracture_energy);
}

}  // namespace coldspray::bonding
