// The short-range repulsion between points of different bodies (Silling and Askari 2005,
// §"short-range forces"; Parks et al., Comput. Phys. Commun. 179 (2008) 777, as LAMMPS's PERI
// package implements it): a pair closer than its contact distance d (pd/laws/contact_pair.hpp)
// pushes apart with force density
//   f = k_c c (d - r) / delta V_j  along the line between them,
// c = 18 K / (pi delta^4) the bond micromodulus. It holds nothing together.
#pragma once

#include <Eigen/Core>
#include <string_view>

#include "pd/laws/contact_pair.hpp"

namespace coldspray::pd {

struct Repulsive {
  static constexpr std::string_view kName = "repulsive";
  static constexpr bool kAdhesive = false;  // whether holds() can be true
  double reach = 0.0;                       // m: no force beyond
  ContactDistance contact;
  double stiffness = 0.0;  // k_c c / delta, N/m^7

  // d = repulsion.distance x the finer spacing, at most repulsion.initial_fraction of the pair's
  // distance at t = 0; k_c = repulsion.stiffness (contact.peridynamics.repulsion).
  static Repulsive make(const ContactLawInputs& in);

  // The force density on i, N/m^3, at separation r = y_i - y_j of length 0 < |r| < reach.
  Eigen::Vector3d force(const ContactPair& p, const Eigen::Vector3d& r, double length) const {
    const double d = contact.of(p);
    if (length >= d) return Eigen::Vector3d::Zero();
    return stiffness * (d - length) * p.N.volume[p.j] / length * r;
  }
  bool holds(const ContactPair&) const { return false; }
};

}  // namespace coldspray::pd
