#include "pd/forces.hpp"

#include "pd/deformation.hpp"
#include "pd/quadratic_fit.hpp"
#include "pd/tensor_field.hpp"

namespace coldspray::pd {

Eigen::Vector3d contact_force(const State& s, std::size_t i, std::size_t j) {
  const Neighbours& N = s.neighbours;
  const ContactLaw& law = s.contact_law[N.body[i] * s.bodies.size() + N.body[j]];
  const Eigen::Vector3d r = vector_at(N.position, i) - vector_at(N.position, j);
  const double length = r.norm();
  if (length >= law.distance || length == 0.0) return Eigen::Vector3d::Zero();
  return law.stiffness * (law.distance - length) * N.volume[j] / length * r;
}

ForceDensity force_density(const State& s, std::size_t i) {
  const Neighbours& N = s.neighbours;
  const std::size_t b = N.body[i];
  const double delta = s.body_bonds[b].horizon;
  const double control = s.settings.stabilization * s.body_bonds[b].micromodulus;
  const Eigen::Vector3d y_i = vector_at(N.position, i);
  // The sums over j of the terms that hold only i's quantities, from the family's fixed sums.
  Eigen::Vector3d bonds = tensor_at(s.piola_over_shape, i) * s.family_sums[i].bond;
  Eigen::Vector3d stabilising = -(s.quadratic_fit[i] * s.family_sums[i].control);
  for_each_bond(
      s.families, N, s.settings.influence, delta, i,
      [&](std::size_t, std::size_t j, const Eigen::Vector3d& xi, double length, double w) {
        // T[x_i]<xi> - T[x_j]<-xi> = omega (A_i + A_j) xi (eq 7); the A_i part is above.
        bonds.noalias() += w * (tensor_at(s.piola_over_shape, j) * xi);
        if (control == 0.0) return;
        // The non-uniform parts z of the bond (Silling 2017), measured against each end's
        // second-order fit: z_i = Y - C_i q(xi) at i (its C_i part above), and at j, with the
        // sign of i's side, Y + C_j q(-xi).
        const Eigen::Vector3d Y = vector_at(N.position, j) - y_i;
        const Monomials q = reversed(monomials(xi, delta));
        stabilising.noalias() += w / length * (2.0 * Y + s.quadratic_fit[j] * q);
      });
  stabilising *= control;
  Eigen::Vector3d contact = Eigen::Vector3d::Zero();
  for (std::size_t c = s.contact.begin[i]; c < s.contact.begin[i + 1]; ++c)
    contact += contact_force(s, i, s.contact.other[c]);
  return {bonds, stabilising, contact};
}

}  // namespace coldspray::pd
