#include "pd/forces.hpp"

#include "pd/deformation.hpp"
#include "pd/quadratic_fit.hpp"
#include "pd/tensor_field.hpp"

namespace coldspray::pd {

Eigen::Vector3d contact_force(const State& s, std::size_t i, std::size_t j) {
  const Neighbours& N = s.neighbours;
  const ContactLaw& law = s.contact_law[N.body[i] * s.bodies.size() + N.body[j]];
  const Eigen::Vector3d r = (N.position[i] - N.position[j]).head<3>();
  const double length = r.norm();
  if (length >= law.distance || length == 0.0) return Eigen::Vector3d::Zero();
  return law.stiffness * (law.distance - length) * N.volume[j] / length * r;
}

ForceDensity force_density(const State& s, std::size_t i) {
  const Neighbours& N = s.neighbours;
  const std::size_t b = N.body[i];
  const BondWeights weights = bond_weights(s, b);
  const double delta = weights.delta;
  const double control = s.settings.stabilization * s.body_bonds[b].micromodulus;
  const Eigen::Vector4d y_i = N.position[i];
  // The sums over j of the terms that hold only i's quantities, from the family's fixed sums.
  Eigen::Vector4d bonds = s.piola_over_shape[i] * s.family_sums[i].bond;
  Eigen::Vector4d stabilising = -(s.quadratic_fit[i] * s.family_sums[i].control);
  for_each_bond(
      s.families, N, weights, i,
      [&](std::size_t, std::size_t j, const Eigen::Vector3d& xi, double length, double w)
          __attribute__((always_inline)) {
            // T[x_i]<xi> - T[x_j]<-xi> = omega (A_i + A_j) xi (eq 7); the A_i part is above.
            const PaddedTensor& A_j = s.piola_over_shape[j];
            bonds += w * (xi[0] * A_j.col(0) + xi[1] * A_j.col(1) + xi[2] * A_j.col(2));
            if (control == 0.0) return;
            // The non-uniform parts z of the bond (Silling 2017), measured against each end's
            // second-order fit: z_i = Y - C_i q(xi) at i (its C_i part above), and at j, with the
            // sign of i's side, Y + C_j q(-xi).
            const Monomials q = reversed(monomials(xi, delta));
            const QuadraticMap& C = s.quadratic_fit[j];
            // C_j q(-xi), in three independent chains.
            const Eigen::Vector4d Cq = (q[0] * C.col(0) + q[1] * C.col(1) + q[2] * C.col(2)) +
                                       (q[3] * C.col(3) + q[4] * C.col(4) + q[5] * C.col(5)) +
                                       (q[6] * C.col(6) + q[7] * C.col(7) + q[8] * C.col(8));
            stabilising += w / length * (2.0 * (N.position[j] - y_i) + Cq);
          });
  stabilising *= control;
  return {bonds.head<3>(), stabilising.head<3>(), contact_density(s, i)};
}

Eigen::Vector3d contact_density(const State& s, std::size_t i) {
  Eigen::Vector3d contact = Eigen::Vector3d::Zero();
  for (std::size_t c = s.contact.begin[i]; c < s.contact.begin[i + 1]; ++c)
    contact += contact_force(s, i, s.contact.other[c]);
  return contact;
}

}  // namespace coldspray::pd
