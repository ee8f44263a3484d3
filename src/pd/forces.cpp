#include "pd/forces.hpp"

#include <algorithm>
#include <cstdint>
#include <variant>

#include "pd/control_along_flow.hpp"
#include "pd/deformation.hpp"
#include "pd/quadratic_fit.hpp"
#include "pd/tensor_field.hpp"

namespace coldspray::pd {

Eigen::Vector3d contact_force(const State& s, std::size_t i, std::size_t candidate) {
  const Neighbours& N = s.neighbours;
  const std::size_t j = s.contact.other[candidate];
  const Eigen::Vector3d r = (N.position[i] - N.position[j]).head<3>();
  const double length = r.norm();
  // One dispatch per candidate pair to the law between their bodies, whose force inlines.
  return std::visit(
      [&](const auto& law) -> Eigen::Vector3d {
        if (length >= law.reach || length == 0.0) return Eigen::Vector3d::Zero();
        return law.force({N, s.contact, i, j, candidate}, r, length);
      },
      contact_law_between(s, i, j));
}

Eigen::Vector4d control_displacement(const State& s, std::size_t i, std::size_t j,
                                     std::size_t bond) {
  const PairSchedule& p = s.pairs;
  if (j > i) {
    const Eigen::Vector3d& e = s.control_displacement[p.pair(i, bond)];
    return {e[0], e[1], e[2], 0.0};
  }
  const Families& fam = s.families;
  const auto first = fam.neighbour.begin() + static_cast<std::ptrdiff_t>(fam.begin[j]);
  const auto end = fam.neighbour.begin() + static_cast<std::ptrdiff_t>(fam.begin[j + 1]);
  const auto at = std::lower_bound(first, end, static_cast<std::uint32_t>(i));
  const std::size_t bond_of_j = static_cast<std::size_t>(at - fam.neighbour.begin());
  const Eigen::Vector3d& e = s.control_displacement[p.pair(j, bond_of_j)];
  return {-e[0], -e[1], -e[2], 0.0};
}

ForceDensity force_density(const State& s, std::size_t i) {
  const Neighbours& N = s.neighbours;
  const std::size_t b = N.body[i];
  const BondWeights weights = bond_weights(s, b);
  const double delta = weights.delta;
  const double control = s.body_bonds[b].control;
  const bool along_flow = control != 0.0 && !s.control_displacement.empty();
  const Eigen::Vector4d y_i = N.position[i], v_i = N.velocity[i];
  // The term of eq 8 that holds only i's A, from the family's fixed sum.
  Eigen::Vector4d bonds = s.piola_over_shape[i] * s.family_sums[i].bond;
  Eigen::Vector4d stabilising = Eigen::Vector4d::Zero();
  for_each_bond(
      s.families, N, weights, i,
      [&](std::size_t bond, std::size_t j, const Eigen::Vector3d& xi, double /*|xi|*/, double w) {
        // T[x_i]<xi> - T[x_j]<-xi> = omega (A_i + A_j) xi (eq 7); the A_i part is above.
        const PaddedTensor& A_j = s.piola_over_shape[j];
        bonds += w * (xi[0] * A_j.col(0) + xi[1] * A_j.col(1) + xi[2] * A_j.col(2));
        if (control == 0.0) return;
        // The rates of the non-uniform parts z of the bond (Silling 2017), measured against each
        // end's second-order fit: zdot_i = V - Cdot_i q(xi), and at j, with the sign of i's
        // side, V + Cdot_j q(-xi); less the parts each end's flow softens.
        const Monomials q = monomials(xi, delta);
        const Eigen::Vector4d V = N.velocity[j] - v_i;
        const Eigen::Vector4d zdot_i = V - s.velocity_fit[i] * q;
        const Eigen::Vector4d zdot_j = V + s.velocity_fit[j] * reversed(q);
        Eigen::Vector4d zdot = zdot_i + zdot_j;
        if (along_flow) {
          // Less the pair's slip rate, plus its fit's share (s.slip_fit, pd/pair_forces.hpp).
          const Eigen::Vector4d Y = N.position[j] - y_i;
          const Eigen::Vector4d e = control_displacement(s, i, j, bond);
          zdot -= softened_part(s.flow_direction[i], s.flow_softening[i], Y, zdot_i, e) +
                  softened_part(s.flow_direction[j], s.flow_softening[j], Y, zdot_j, e);
          zdot += s.slip_fit[i] * q - s.slip_fit[j] * reversed(q);
        }
        stabilising += w * zdot;
      });
  stabilising *= control;
  return {bonds.head<3>(), stabilising.head<3>(), contact_density(s, i)};
}

std::uint16_t adhesive_partner(const State& s, std::size_t i) {
  const Neighbours& N = s.neighbours;
  for (std::size_t c = s.contact.begin[i]; c < s.contact.begin[i + 1]; ++c) {
    const std::size_t j = s.contact.other[c];
    const ContactPair pair{N, s.contact, i, j, c};
    const bool holds =
        std::visit([&](const auto& law) { return law.holds(pair); }, contact_law_between(s, i, j));
    if (holds) return static_cast<std::uint16_t>(1 + N.body[j]);
  }
  return 0;
}

Eigen::Vector3d contact_density(const State& s, std::size_t i) {
  Eigen::Vector3d contact = Eigen::Vector3d::Zero();
  for (std::size_t c = s.contact.begin[i]; c < s.contact.begin[i + 1]; ++c)
    contact += contact_force(s, i, c);
  return contact;
}

}  // namespace coldspray::pd
