#include "studies/deposit_placement.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <numbers>
#include <random>
#include <unordered_map>

#include "core/interrupt.hpp"

namespace coldspray::studies {

namespace {

// The draws, written out rather than taken from std::uniform_real_distribution and
// std::normal_distribution, whose algorithms each standard library chooses: the engine
// (std::mt19937_64) is fixed by the standard, so the same seed gives the same deposit with any
// compiler.
class Draws {
 public:
  explicit Draws(std::uint64_t seed) : engine_(seed) {}

  // Uniform on [0, 1): the engine's top 53 bits as a double's mantissa.
  double uniform() { return static_cast<double>(engine_() >> 11) * 0x1.0p-53; }

  // Standard normal by the Box-Muller transform (Box & Muller 1958, Ann. Math. Stat. 29:610),
  // one of the pair per call: u1 in (0, 1] keeps the logarithm finite.
  double normal() {
    const double u1 = 1.0 - uniform();
    const double u2 = uniform();
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }

  // Standard normal within kSizeDeviations: drawn again while outside. A draw falls outside
  // three deviations with probability 0.0027, so kRedraws = 100 in a row have 0.0027^100 ~ 1e-257:
  // the bound never changes a deposit, and keeps the loop finite; the last draw is then clamped.
  double bounded_normal() {
    constexpr int kRedraws = 100;
    double z = 0.0;
    for (int k = 0; k < kRedraws; ++k) {
      z = normal();
      if (std::abs(z) <= kSizeDeviations) return z;
    }
    return std::clamp(z, -kSizeDeviations, kSizeDeviations);
  }

 private:
  std::mt19937_64 engine_;
};

double draw_size(const SizeDistribution& d, Draws& draws) {
  switch (d.kind) {
    case SizeDistribution::Kind::Fixed:
      return d.centre;
    case SizeDistribution::Kind::Normal:
      return d.centre + d.spread * draws.bounded_normal();
    case SizeDistribution::Kind::LogNormal:
      // ln d is normal with mean ln(median) and deviation ln(geometric deviation).
      return d.centre * std::pow(d.spread, draws.bounded_normal());
  }
  return d.centre;
}

bool overlaps(const PlacedParticle& a, const PlacedParticle& b, double clearance) {
  double distance2 = 0.0;
  for (int k = 0; k < 3; ++k)
    distance2 += (a.centre[k] - b.centre[k]) * (a.centre[k] - b.centre[k]);
  const double reach = 0.5 * (a.diameter + b.diameter) + clearance;
  return distance2 < reach * reach;
}

std::vector<double> draw_diameters(const DepositPlan& plan, Draws& draws) {
  std::vector<double> d(static_cast<std::size_t>(plan.count));
  for (double& x : d) x = draw_size(plan.diameter, draws);
  return d;
}

// The particles placed so far, binned by centre into cubic cells of edge `cell`, at least the
// farthest two particles can reach (the largest diameter and the clearance): a particle can only
// overlap those in the 27 cells around its centre's. Checking them instead of every particle
// placed makes a draw cost the same however many are placed (the check over all was N^2 / 2
// distances for N particles: 5e9 for 100 000); the answer is the same.
class PlacedCells {
 public:
  PlacedCells(const std::vector<PlacedParticle>& placed, double cell, double clearance)
      : placed_(placed), cell_(cell), clearance_(clearance) {}

  bool clear(const PlacedParticle& p) const {
    const std::array<std::int64_t, 3> c = cell_of(p);
    for (std::int64_t k = c[2] - 1; k <= c[2] + 1; ++k)
      for (std::int64_t j = c[1] - 1; j <= c[1] + 1; ++j)
        for (std::int64_t i = c[0] - 1; i <= c[0] + 1; ++i) {
          const auto found = cells_.find(key({i, j, k}));
          if (found == cells_.end()) continue;
          for (const std::size_t q : found->second)
            if (overlaps(p, placed_[q], clearance_)) return false;
        }
    return true;
  }

  void add(std::size_t q) { cells_[key(cell_of(placed_[q]))].push_back(q); }

 private:
  std::array<std::int64_t, 3> cell_of(const PlacedParticle& p) const {
    std::array<std::int64_t, 3> c{};
    for (int d = 0; d < 3; ++d) c[d] = static_cast<std::int64_t>(std::floor(p.centre[d] / cell_));
    return c;
  }
  // 21 bits a coordinate: cells 2^21 apart (29 m for a 14 um particle) share a key, which costs
  // only a few distances more, and neighbouring cells never do.
  static std::int64_t key(const std::array<std::int64_t, 3>& c) {
    constexpr std::int64_t kMask = (std::int64_t{1} << 21) - 1;
    return ((c[2] & kMask) << 42) | ((c[1] & kMask) << 21) | (c[0] & kMask);
  }

  const std::vector<PlacedParticle>& placed_;
  double cell_, clearance_;
  std::unordered_map<std::int64_t, std::vector<std::size_t>> cells_;
};

}  // namespace

double SizeDistribution::smallest() const {
  switch (kind) {
    case Kind::Fixed:
      return centre;
    case Kind::Normal:
      return centre - kSizeDeviations * spread;
    case Kind::LogNormal:
      return centre / std::pow(spread, kSizeDeviations);
  }
  return centre;
}

double SizeDistribution::largest() const {
  switch (kind) {
    case Kind::Fixed:
      return centre;
    case Kind::Normal:
      return centre + kSizeDeviations * spread;
    case Kind::LogNormal:
      return centre * std::pow(spread, kSizeDeviations);
  }
  return centre;
}

double DepositPlan::speed_of(double d) const {
  return speed * std::pow(d / speed_diameter, speed_exponent);
}

std::vector<double> draw_diameters(const DepositPlan& plan) {
  Draws draws(plan.seed);
  return draw_diameters(plan, draws);
}

Placement place_particles(const DepositPlan& plan) {
  Draws draws(plan.seed);
  Placement out;
  std::vector<PlacedParticle>& placed = out.particles;
  const std::vector<double> diameters = draw_diameters(plan, draws);
  placed.resize(diameters.size());
  for (std::size_t i = 0; i < placed.size(); ++i) {
    placed[i].diameter = diameters[i];
    placed[i].speed = plan.speed_of(diameters[i]);
  }
  const double largest =
      diameters.empty() ? 0.0 : *std::max_element(diameters.begin(), diameters.end());
  PlacedCells cells(placed, largest + plan.clearance, plan.clearance);
  for (std::size_t i = 0; i < placed.size(); ++i) {
    stop_set_up_if_interrupted("placing particles");
    PlacedParticle& p = placed[i];
    bool clear = false;
    for (int attempt = 0; attempt < kPlacementTries && !clear; ++attempt) {
      p.arrival = i == 0 ? 0.0 : plan.arrival_window * draws.uniform();
      p.centre[0] = plan.patch[0] * (draws.uniform() - 0.5);
      p.centre[1] = plan.patch[1] * (draws.uniform() - 0.5);
      p.centre[2] = p.speed * p.arrival + 0.5 * p.diameter;
      clear = cells.clear(p);
    }
    if (!clear) {
      out.unplaced = static_cast<int>(i);
      placed.resize(i);
      return out;
    }
    cells.add(i);
  }
  // In arrival order; the first drawn arrives at 0 and stays first.
  std::stable_sort(
      placed.begin(), placed.end(),
      [](const PlacedParticle& a, const PlacedParticle& b) { return a.arrival < b.arrival; });
  return out;
}

}  // namespace coldspray::studies
