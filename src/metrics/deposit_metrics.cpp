#include "metrics/deposit_metrics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace coldspray::metrics {

namespace {

// The voxels i (along one axis, from `origin`) whose centres origin + (i + 1/2) edge lie in
// [lo, hi), clamped to [0, count): [first, last).
std::array<int, 2> centres_within(double lo, double hi, double origin, double edge, int count) {
  const auto first = static_cast<long>(std::ceil((lo - origin) / edge - 0.5));
  const auto last = static_cast<long>(std::ceil((hi - origin) / edge - 0.5));
  return {static_cast<int>(std::clamp<long>(first, 0, count)),
          static_cast<int>(std::clamp<long>(last, 0, count))};
}

}  // namespace

DepositVoxels voxelise_deposit(const bodies::Bodies& s, const std::vector<bool>& is_deposit,
                               std::size_t substrate, std::array<double, 2> patch, double edge,
                               double speed_limit, double surface_z) {
  const bodies::Points& P = s.points;
  auto counted = [&](std::size_t b, std::size_t p) {
    return b == substrate || (is_deposit[b] && bodies::speed(P, p) <= speed_limit);
  };
  auto in_patch = [&](std::size_t p) {
    return std::abs(P.position[0][p]) - P.half_width[0][p] < 0.5 * patch[0] &&
           std::abs(P.position[1][p]) - P.half_width[1][p] < 0.5 * patch[1];
  };
  // The z range: the substrate's top layer's lowest point to the deposit's highest.
  double z_lo = std::numeric_limits<double>::max(), z_hi = std::numeric_limits<double>::lowest();
  const bodies::BodyRange& sub = s.bodies[substrate];
  for (std::size_t p = sub.begin; p < sub.end; ++p)
    if (P.initial_z[p] > surface_z - sub.spacing && in_patch(p))
      z_lo = std::min(z_lo, P.position[2][p] - P.half_width[2][p]);
  for (std::size_t b = 0; b < s.bodies.size(); ++b)
    if (b != substrate && is_deposit[b])
      for (std::size_t p = s.bodies[b].begin; p < s.bodies[b].end; ++p)
        if (counted(b, p) && in_patch(p)) {
          z_lo = std::min(z_lo, P.position[2][p] - P.half_width[2][p]);
          z_hi = std::max(z_hi, P.position[2][p] + P.half_width[2][p]);
        }
  if (z_lo > z_hi) z_lo = z_hi = surface_z;  // nothing in the patch

  DepositVoxels v;
  v.edge = edge;
  for (int d = 0; d < 2; ++d) {
    v.count[d] = static_cast<int>(std::ceil(patch[d] / edge - 1e-9));
    v.origin[d] = -0.5 * v.count[d] * edge;
  }
  v.origin[2] = std::floor(z_lo / edge) * edge;
  v.count[2] = std::max(1, static_cast<int>(std::ceil((z_hi - v.origin[2]) / edge - 1e-9)));
  v.mark.assign(static_cast<std::size_t>(v.count[0]) * v.count[1] * v.count[2], 0);

  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    if (b != substrate && !is_deposit[b]) continue;
    const std::uint8_t bit = b == substrate ? DepositVoxels::kSubstrate : DepositVoxels::kDeposit;
    for (std::size_t p = s.bodies[b].begin; p < s.bodies[b].end; ++p) {
      if (!counted(b, p)) continue;
      std::array<std::array<int, 2>, 3> range;
      for (int d = 0; d < 3; ++d)
        range[d] =
            centres_within(P.position[d][p] - P.half_width[d][p],
                           P.position[d][p] + P.half_width[d][p], v.origin[d], edge, v.count[d]);
      for (int k = range[2][0]; k < range[2][1]; ++k)
        for (int j = range[1][0]; j < range[1][1]; ++j)
          for (int i = range[0][0]; i < range[0][1]; ++i) v.mark[v.index(i, j, k)] |= bit;
    }
  }
  return v;
}

DepositShape deposit_shape(const DepositVoxels& v, double surface_z) {
  DepositShape out;
  const std::size_t columns = static_cast<std::size_t>(v.count[0]) * v.count[1];
  out.columns = {v.count[0], v.count[1]};
  out.thickness.assign(columns, 0.0);
  long envelope = 0, voids = 0, covered = 0;
  for (int j = 0; j < v.count[1]; ++j)
    for (int i = 0; i < v.count[0]; ++i) {
      auto marked = [&](int k, std::uint8_t bit) { return (v.mark[v.index(i, j, k)] & bit) != 0; };
      int lowest = -1, highest = -1;
      for (int k = 0; k < v.count[2]; ++k)
        if (marked(k, DepositVoxels::kDeposit)) {
          if (lowest < 0) lowest = k;
          highest = k;
        }
      if (highest < 0) continue;
      int start = lowest;
      while (start > 0 && !marked(start - 1, DepositVoxels::kSubstrate)) --start;
      ++covered;
      envelope += highest - start + 1;
      for (int k = start; k <= highest; ++k) voids += v.mark[v.index(i, j, k)] == 0 ? 1 : 0;
      const double top = v.origin[2] + (highest + 1) * v.edge - surface_z;
      out.thickness[static_cast<std::size_t>(i) + static_cast<std::size_t>(v.count[0]) * j] =
          std::max(top, 0.0);
    }
  if (columns == 0) return out;
  out.porosity = envelope > 0 ? static_cast<double>(voids) / static_cast<double>(envelope) : 0.0;
  double sum = 0.0;
  for (double t : out.thickness) {
    sum += t;
    out.max_thickness = std::max(out.max_thickness, t);
  }
  out.mean_thickness = sum / static_cast<double>(columns);
  out.coverage = static_cast<double>(covered) / static_cast<double>(columns);
  return out;
}

double deposition_efficiency(const std::vector<double>& sprayed_mass,
                             const std::vector<bool>& bonded) {
  double total = 0.0, kept = 0.0;
  for (std::size_t i = 0; i < sprayed_mass.size(); ++i) {
    total += sprayed_mass[i];
    if (bonded[i]) kept += sprayed_mass[i];
  }
  return total > 0.0 ? kept / total : 0.0;
}

}  // namespace coldspray::metrics
