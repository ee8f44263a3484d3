#include "run/verdict_series.hpp"

#include "metrics/impact_metrics.hpp"

namespace coldspray::run {

VerdictSeries::VerdictSeries(const case_file::ImpactMetrics& m, const bodies::Bodies& s)
    : rule_{m.verdict_window, m.bonded_separation_speed, s.bonding},
      interval_(m.verdict_window / kSamplesPerWindow),
      bodies_(s.bodies.size()),
      // The window's samples and those of the steps before it that due() takes (at most
      // 2 + 2 dt / interval more), and the one at the end, which may fall between two scheduled
      // ones: the oldest are overwritten.
      capacity_(kSamplesPerWindow + 8),
      schedule_(interval_) {
  for (std::size_t b = 0; b < s.bodies.size(); ++b) {
    const double v0 = s.bodies[b].initial_velocity[2];
    if (v0 == 0.0) {
      resting_.push_back(b);
    } else {
      moving_.push_back(b);
      away_.push_back(v0 < 0.0 ? 1.0 : -1.0);
    }
  }
  ring_.resize(capacity_ * moving_.size());
}

bool VerdictSeries::due(const bodies::Bodies& s, const StepRule& rule) const {
  // From a step or two before the window on (dt changes little from one step to the next), so
  // that a sample precedes its start.
  const double from = rule.end - rule_.window - 2.0 * (interval_ + s.dt);
  if (moving_.empty() || s.time < from) return false;
  return schedule_.due(s.time) || rule.finished(s);
}

namespace {

// The z velocity of the points at rest, mass-averaged; of all the points when none is at rest (at
// first contact every point of a particle moves at the impact speed); 0, the frame, for none.
double rest_velocity(const metrics::RestAndBond& r) {
  if (r.rest_mass > 0.0) return r.rest_momentum_z / r.rest_mass;
  return r.mass > 0.0 ? r.momentum_z / r.mass : 0.0;
}

}  // namespace

void VerdictSeries::sample(const bodies::Bodies& s) {
  schedule_.done(s.time);
  // The substrate's velocity, its bodies together, without the jetting of its crater's rim.
  metrics::RestAndBond substrate;
  for (const std::size_t b : resting_) {
    const metrics::RestAndBond r = metrics::rest_and_bond(s, b);
    substrate.mass += r.mass;
    substrate.momentum_z += r.momentum_z;
    substrate.rest_mass += r.rest_mass;
    substrate.rest_momentum_z += r.rest_momentum_z;
  }
  const double v_substrate = rest_velocity(substrate);
  for (std::size_t k = 0; k < moving_.size(); ++k) {
    const metrics::RestAndBond r = metrics::rest_and_bond(s, moving_[k]);
    ring_[k * capacity_ + next_] = {s.time, away_[k] * (rest_velocity(r) - v_substrate),
                                    r.bonded_area};
  }
  next_ = (next_ + 1) % capacity_;
  if (count_ < capacity_) ++count_;
}

metrics::Verdict VerdictSeries::verdict(std::size_t k) const {
  std::vector<metrics::VerdictSample> series;
  series.reserve(count_);
  const std::size_t oldest = count_ < capacity_ ? 0 : next_;
  for (std::size_t i = 0; i < count_; ++i)
    series.push_back(ring_[k * capacity_ + (oldest + i) % capacity_]);
  return metrics::decide(series, rule_);
}

std::vector<std::optional<metrics::Verdict>> VerdictSeries::verdicts() const {
  std::vector<std::optional<metrics::Verdict>> out(bodies_);
  for (std::size_t k = 0; k < moving_.size(); ++k) out[moving_[k]] = verdict(k);
  return out;
}

bool VerdictSeries::undecided() const {
  for (std::size_t k = 0; k < moving_.size(); ++k)
    if (verdict(k).outcome == metrics::Outcome::Undecided) return true;
  return false;
}

}  // namespace coldspray::run
