#include "pd/pair_forces.hpp"

#include <algorithm>
#include <type_traits>

#include "pd/control_along_flow.hpp"
#include "pd/deformation.hpp"
#include "pd/quadratic_fit.hpp"
#include "pd/symmetry.hpp"

namespace coldspray::pd {

PairSchedule pair_schedule(const Families& fam, std::size_t real) {
  PairSchedule schedule;
  schedule.first_pair.resize(real);
  schedule.pair_index.resize(real + 1, 0);
  std::size_t reach = 1;  // the largest j - i over the pairs of real points
  for (std::size_t i = 0; i < real; ++i) {
    const auto first = fam.neighbour.begin() + static_cast<std::ptrdiff_t>(fam.begin[i]);
    const auto end = fam.neighbour.begin() + static_cast<std::ptrdiff_t>(fam.begin[i + 1]);
    const auto above = std::upper_bound(first, end, static_cast<std::uint32_t>(i));
    schedule.first_pair[i] = static_cast<std::size_t>(above - fam.neighbour.begin());
    schedule.pair_index[i + 1] = schedule.pair_index[i] + static_cast<std::size_t>(end - above);
    for (auto j = above; j != end && *j < real; ++j) reach = std::max<std::size_t>(reach, *j - i);
  }
  for (std::size_t start = 0; start < real; start += reach) schedule.block.push_back(start);
  schedule.block.push_back(real);
  return schedule;
}

namespace {

// The pairs (i, j > i) of the points [first, end): eq 8's omega (A_i + A_j) xi beta V and the
// control's rate omega beta V zdot, zdot = zdot_i + zdot_j less the parts the flow
// softens (pd/forces.hpp), i's part of each pair to i and j's to j (real j only). With the
// control along the flow each pair's penalty displacement e advances by dt zdot. The part of
// eq 8 that holds only the point's own A is added apart (pair_forces), as is the control's
// factor G_s c / l (pd/control_length.hpp).
template <case_file::Influence kind, bool along_flow>
void visit_pairs(State& s, const BondWeights& weights, bool controlled, std::size_t first,
                 std::size_t end) {
  const Families& fam = s.families;
  const Neighbours& N = s.neighbours;
  const double delta = weights.delta;
  for (std::size_t i = first; i < end; ++i) {
    const Eigen::Vector4d X_i = N.reference[i], y_i = N.position[i], v_i = N.velocity[i];
    const PaddedTensor A_i = s.piola_over_shape[i];
    const QuadraticMap C_i = s.velocity_fit[i];
    const double V_i = N.volume[i];
    Eigen::Vector4d bonds = Eigen::Vector4d::Zero(), control = Eigen::Vector4d::Zero();
    QuadraticMap slip_sum = QuadraticMap::Zero();
    for (std::size_t b = s.pairs.first_pair[i]; b < fam.begin[i + 1]; ++b) {
      const std::size_t j = fam.neighbour[b];
      const Eigen::Vector3d xi = (N.reference[j] - X_i).head<3>();
      const double length = xi.norm();
      const double omega_beta = influence<kind>(length, delta) * fam.volume_fraction(b);
      const double w_ij = omega_beta * N.volume[j], w_ji = omega_beta * V_i;
      const bool real = j < N.real;
      const PaddedTensor& A_j = s.piola_over_shape[j];
      bonds += w_ij * (xi[0] * A_j.col(0) + xi[1] * A_j.col(1) + xi[2] * A_j.col(2));
      if (real)
        s.pair_bonds[j] -= w_ji * (xi[0] * A_i.col(0) + xi[1] * A_i.col(1) + xi[2] * A_i.col(2));
      if (!controlled) continue;
      // zdot_i = V - Cdot_i q(xi) and, with the sign of i's side, zdot_j = V + Cdot_j q(-xi).
      const Monomials q = monomials(xi, delta);
      const Monomials r = reversed(q);
      const QuadraticMap& C_j = s.velocity_fit[j];
      const Eigen::Vector4d V = N.velocity[j] - v_i;
      const Eigen::Vector4d zdot_i =
          V - ((q[0] * C_i.col(0) + q[1] * C_i.col(1) + q[2] * C_i.col(2)) +
               (q[3] * C_i.col(3) + q[4] * C_i.col(4) + q[5] * C_i.col(5)) +
               (q[6] * C_i.col(6) + q[7] * C_i.col(7) + q[8] * C_i.col(8)));
      const Eigen::Vector4d zdot_j =
          V + ((r[0] * C_j.col(0) + r[1] * C_j.col(1) + r[2] * C_j.col(2)) +
               (r[3] * C_j.col(3) + r[4] * C_j.col(4) + r[5] * C_j.col(5)) +
               (r[6] * C_j.col(6) + r[7] * C_j.col(7) + r[8] * C_j.col(8)));
      Eigen::Vector4d zdot = zdot_i + zdot_j;
      if constexpr (along_flow) {
        Eigen::Vector3d& e = s.control_displacement[s.pairs.pair(i, b)];
        const double a_i = s.flow_softening[i], a_j = s.flow_softening[j];
        if (a_i != 0.0 || a_j != 0.0) {
          // The pair's slip rate, the parts its ends' flow softens, and half of it into each
          // end's fit (with j's sign and bond -xi at j).
          const Eigen::Vector4d Y = N.position[j] - y_i;
          const Eigen::Vector4d e4(e[0], e[1], e[2], 0.0);
          const Eigen::Vector4d slip = softened_part(s.flow_direction[i], a_i, Y, zdot_i, e4) +
                                       softened_part(s.flow_direction[j], a_j, Y, zdot_j, e4);
          zdot -= slip;
          const Eigen::Vector4d half = 0.5 * slip;
          for (int k = 0; k < 9; ++k) slip_sum.col(k) += (w_ij * q[k]) * half;
          if (real)
            for (int k = 0; k < 9; ++k) s.slip_fit[j].col(k) -= (w_ji * r[k]) * half;
        }
        e += s.dt * zdot.head<3>();
      }
      control += w_ij * zdot;
      if (real) s.pair_control[j] -= w_ji * zdot;
    }
    s.pair_bonds[i] += bonds;
    s.pair_control[i] += control;
    if constexpr (along_flow) s.slip_fit[i] += slip_sum;
  }
}

// The second pass of the control along the flow: with D the fit of half the slip rates
// (pd/control_along_flow.hpp), each pair's zdot gains D_i q(xi) - D_j q(-xi), so that the ends'
// fits are those of the bond less its slip; to e and to both ends as in visit_pairs.
template <case_file::Influence kind>
void visit_slip_pairs(State& s, const BondWeights& weights, std::size_t first, std::size_t end) {
  const Families& fam = s.families;
  const Neighbours& N = s.neighbours;
  const double delta = weights.delta;
  for (std::size_t i = first; i < end; ++i) {
    const Eigen::Vector4d X_i = N.reference[i];
    const QuadraticMap D_i = s.slip_fit[i];
    const double V_i = N.volume[i];
    Eigen::Vector4d control = Eigen::Vector4d::Zero();
    const bool slipped_i = !D_i.isZero(0.0);
    for (std::size_t b = s.pairs.first_pair[i]; b < fam.begin[i + 1]; ++b) {
      const std::size_t j = fam.neighbour[b];
      // (Most pairs, away from the flow, have no slip fit at either end.)
      if (!slipped_i && !s.slipped[j]) continue;
      const QuadraticMap& D_j = s.slip_fit[j];
      const Eigen::Vector3d xi = (N.reference[j] - X_i).head<3>();
      const double length = xi.norm();
      const double omega_beta = influence<kind>(length, delta) * fam.volume_fraction(b);
      const Monomials q = monomials(xi, delta);
      const Eigen::Vector4d kappa = D_i * q - D_j * reversed(q);
      s.control_displacement[s.pairs.pair(i, b)] += s.dt * kappa.head<3>();
      control += omega_beta * N.volume[j] * kappa;
      if (j < N.real) s.pair_control[j] -= omega_beta * V_i * kappa;
    }
    s.pair_control[i] += control;
  }
}

// pass(weights, influence tag, from, to) over [first, end), body by body (a block may span two
// bodies).
template <class Pass>
void visit_block(State& s, std::size_t first, std::size_t end, Pass&& pass) {
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    if (!s.advancing[b]) continue;
    const std::size_t from = std::max(first, s.bodies[b].begin);
    const std::size_t to = std::min(end, s.bodies[b].end);
    if (from >= to) continue;
    const BondWeights weights = bond_weights(s, b);
    if (weights.influence == case_file::Influence::Constant)
      pass(weights, std::integral_constant<case_file::Influence, case_file::Influence::Constant>{},
           from, to);
    else
      pass(weights,
           std::integral_constant<case_file::Influence, case_file::Influence::InverseDistance>{},
           from, to);
  }
}

// pass over every block, the even ones in parallel, then the odd ones.
template <class Pass>
void visit_blocks(State& s, Pass&& pass) {
  const std::size_t blocks = s.pairs.block.size() - 1;
  for (std::size_t colour = 0; colour < 2; ++colour) {
#pragma omp parallel for schedule(dynamic, 1) if (threaded(s))
    for (std::size_t k = colour; k < blocks; k += 2)
      visit_block(s, s.pairs.block[k], s.pairs.block[k + 1], pass);
  }
}

}  // namespace

void pair_forces(State& s) {
  const std::size_t n = s.neighbours.real;
  const bool controlled = s.settings.stabilization != 0.0;
  const bool along_flow = controlled && !s.control_displacement.empty();
  // The terms of eq 8 that hold only the point's own A, from the family's fixed sum
  // (pd/deformation.hpp).
#pragma omp parallel for schedule(static) if (threaded(s))
  for (std::size_t i = 0; i < n; ++i) {
    if (!s.advancing[s.neighbours.body[i]]) continue;
    s.pair_bonds[i] = s.piola_over_shape[i] * s.family_sums[i].bond;
    s.pair_control[i].setZero();
    if (along_flow) s.slip_fit[i].setZero();
  }
  visit_blocks(s, [&](const BondWeights& weights, auto kind, std::size_t from, std::size_t to) {
    if (along_flow)
      visit_pairs<decltype(kind)::value, true>(s, weights, controlled, from, to);
    else
      visit_pairs<decltype(kind)::value, false>(s, weights, controlled, from, to);
  });
  if (along_flow) {
    // D = [sum omega (slip / 2) (x) q V_j] M^-1 (pd/quadratic_fit.hpp), then the second pass.
#pragma omp parallel for schedule(static) if (threaded(s))
    for (std::size_t i = 0; i < n; ++i)
      if (s.advancing[s.neighbours.body[i]])
        s.slip_fit[i] = s.slip_fit[i].lazyProduct(s.moment_inverse[i]).eval();
    refresh_ghost_slip_fits(s);
#pragma omp parallel for schedule(static) if (threaded(s))
    for (std::size_t i = 0; i < s.slip_fit.size(); ++i) s.slipped[i] = !s.slip_fit[i].isZero(0.0);
    visit_blocks(s, [&](const BondWeights& weights, auto kind, std::size_t from, std::size_t to) {
      visit_slip_pairs<decltype(kind)::value>(s, weights, from, to);
    });
  }
#pragma omp parallel for schedule(static) if (threaded(s))
  for (std::size_t i = 0; i < n; ++i)
    if (s.advancing[s.neighbours.body[i]])
      s.pair_control[i] *= s.body_bonds[s.neighbours.body[i]].control;
}

}  // namespace coldspray::pd
