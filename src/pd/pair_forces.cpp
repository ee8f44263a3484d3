#include "pd/pair_forces.hpp"

#include <algorithm>

#include "pd/deformation.hpp"
#include "pd/quadratic_fit.hpp"

namespace coldspray::pd {

PairSchedule pair_schedule(const Families& fam, std::size_t real) {
  PairSchedule schedule;
  schedule.first_pair.resize(real);
  std::size_t reach = 1;  // the largest j - i over the pairs of real points
  for (std::size_t i = 0; i < real; ++i) {
    const auto first = fam.neighbour.begin() + static_cast<std::ptrdiff_t>(fam.begin[i]);
    const auto end = fam.neighbour.begin() + static_cast<std::ptrdiff_t>(fam.begin[i + 1]);
    const auto above = std::upper_bound(first, end, static_cast<std::uint32_t>(i));
    schedule.first_pair[i] = static_cast<std::size_t>(above - fam.neighbour.begin());
    for (auto j = above; j != end && *j < real; ++j) reach = std::max<std::size_t>(reach, *j - i);
  }
  for (std::size_t start = 0; start < real; start += reach) schedule.block.push_back(start);
  schedule.block.push_back(real);
  return schedule;
}

namespace {

// The pairs (i, j > i) of the points [first, end): eq 8's omega (A_i + A_j) xi beta V and the
// control's c / |xi| omega beta V (z_i + z_j) (pd/forces.hpp), i's part of each pair to i and
// j's to j (real j only). The parts that hold only the point's own A and C are added apart
// (pair_forces). The control's factor G_s c is applied there too.
template <case_file::Influence kind>
void visit_pairs(State& s, const BondWeights& weights, bool controlled, std::size_t first,
                 std::size_t end) {
  const Families& fam = s.families;
  const Neighbours& N = s.neighbours;
  const double delta = weights.delta;
  for (std::size_t i = first; i < end; ++i) {
    const Eigen::Vector4d X_i = N.reference[i], y_i = N.position[i];
    const PaddedTensor A_i = s.piola_over_shape[i];
    const QuadraticMap C_i = s.quadratic_fit[i];
    const double V_i = N.volume[i];
    Eigen::Vector4d bonds = Eigen::Vector4d::Zero(), control = Eigen::Vector4d::Zero();
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
      // z_i + z_j seen from i: 2Y - C_i q(xi) + C_j q(-xi); from j, with its sign,
      // -(2Y - C_i q(xi) + C_j q(-xi)) plus the parts of j's own C (added apart).
      const Monomials q = monomials(xi, delta);
      const Monomials r = reversed(q);
      const QuadraticMap& C_j = s.quadratic_fit[j];
      const Eigen::Vector4d Y2 = 2.0 * (N.position[j] - y_i);
      const Eigen::Vector4d Cq_j = (r[0] * C_j.col(0) + r[1] * C_j.col(1) + r[2] * C_j.col(2)) +
                                   (r[3] * C_j.col(3) + r[4] * C_j.col(4) + r[5] * C_j.col(5)) +
                                   (r[6] * C_j.col(6) + r[7] * C_j.col(7) + r[8] * C_j.col(8));
      control += w_ij / length * (Y2 + Cq_j);
      if (real) {
        const Eigen::Vector4d Cq_i = (q[0] * C_i.col(0) + q[1] * C_i.col(1) + q[2] * C_i.col(2)) +
                                     (q[3] * C_i.col(3) + q[4] * C_i.col(4) + q[5] * C_i.col(5)) +
                                     (q[6] * C_i.col(6) + q[7] * C_i.col(7) + q[8] * C_i.col(8));
        s.pair_control[j] -= w_ji / length * (Y2 - Cq_i);
      }
    }
    s.pair_bonds[i] += bonds;
    s.pair_control[i] += control;
  }
}

// visit_pairs over [first, end), body by body (a block may span two bodies).
void visit_block(State& s, std::size_t first, std::size_t end) {
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const std::size_t from = std::max(first, s.bodies[b].begin);
    const std::size_t to = std::min(end, s.bodies[b].end);
    if (from >= to) continue;
    const BondWeights weights = bond_weights(s, b);
    const bool controlled = s.settings.stabilization != 0.0;
    if (weights.influence == case_file::Influence::Constant)
      visit_pairs<case_file::Influence::Constant>(s, weights, controlled, from, to);
    else
      visit_pairs<case_file::Influence::InverseDistance>(s, weights, controlled, from, to);
  }
}

}  // namespace

void pair_forces(State& s) {
  const std::size_t n = s.neighbours.real;
  // The terms of eq 8 and of the control that hold only the point's own A and C, from the
  // family's fixed sums (pd/deformation.hpp).
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    s.pair_bonds[i] = s.piola_over_shape[i] * s.family_sums[i].bond;
    s.pair_control[i] = -(s.quadratic_fit[i] * s.family_sums[i].control);
  }
  const std::size_t blocks = s.pairs.block.size() - 1;
  for (std::size_t colour = 0; colour < 2; ++colour) {
#pragma omp parallel for schedule(dynamic, 1)
    for (std::size_t k = colour; k < blocks; k += 2)
      visit_block(s, s.pairs.block[k], s.pairs.block[k + 1]);
  }
#pragma omp parallel for schedule(static)
  for (std::size_t i = 0; i < n; ++i)
    s.pair_control[i] *= s.settings.stabilization * s.body_bonds[s.neighbours.body[i]].micromodulus;
}

}  // namespace coldspray::pd
