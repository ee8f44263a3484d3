#include "studies/deposit_placement.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>

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

  // Standard normal within kSizeDeviations.
  double bounded_normal() {
    for (;;) {
      const double z = normal();
      if (std::abs(z) <= kSizeDeviations) return z;
    }
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

Placement place_particles(const DepositPlan& plan) {
  Draws draws(plan.seed);
  Placement out;
  std::vector<PlacedParticle>& placed = out.particles;
  placed.resize(static_cast<std::size_t>(plan.count));
  for (PlacedParticle& p : placed) {
    p.diameter = draw_size(plan.diameter, draws);
    p.speed = plan.speed * std::pow(p.diameter / plan.speed_diameter, plan.speed_exponent);
  }
  for (std::size_t i = 0; i < placed.size(); ++i) {
    PlacedParticle& p = placed[i];
    bool clear = false;
    for (int attempt = 0; attempt < kPlacementTries && !clear; ++attempt) {
      p.arrival = i == 0 ? 0.0 : plan.arrival_window * draws.uniform();
      p.centre[0] = plan.patch[0] * (draws.uniform() - 0.5);
      p.centre[1] = plan.patch[1] * (draws.uniform() - 0.5);
      p.centre[2] = p.speed * p.arrival + 0.5 * p.diameter;
      clear = std::none_of(placed.begin(), placed.begin() + i,
                           [&](const PlacedParticle& q) { return overlaps(p, q, plan.clearance); });
    }
    if (!clear) {
      out.unplaced = static_cast<int>(i);
      placed.resize(i);
      return out;
    }
  }
  // In arrival order; the first drawn arrives at 0 and stays first.
  std::stable_sort(
      placed.begin(), placed.end(),
      [](const PlacedParticle& a, const PlacedParticle& b) { return a.arrival < b.arrival; });
  return out;
}

}  // namespace coldspray::studies
