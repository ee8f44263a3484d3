// The series the bonded verdict reads (metrics/verdict.hpp), of every body that moved in z at
// t = 0, sampled while a run goes: at t = 0 (so that a run shorter than its window is read from
// its start), then at a fixed interval of simulated time, kSamplesPerWindow per
// metrics.verdict_window whatever the output settings, from just before the last window of the
// run's current end, and at the end itself; into ring buffers allocated once.
#pragma once

#include <array>
#include <cstddef>
#include <optional>
#include <vector>

#include "bodies/bodies.hpp"
#include "case/case.hpp"
#include "metrics/verdict.hpp"
#include "run/schedule.hpp"
#include "run/step_rule.hpp"

namespace coldspray::run {

// 0.1 ns at the default 20 ns window: 120 samples over the 12 ns period at which stuck particles
// ring, so the trapezoidal means are exact to 2e-4 of the ringing's amplitude.
inline constexpr int kSamplesPerWindow = 200;

class VerdictSeries {
 public:
  // The moving bodies of `s` (the state at t = 0) and the substrate they separate from: the
  // bodies at rest in z then.
  VerdictSeries(const case_file::ImpactMetrics& m, const bodies::Bodies& s);

  // Whether a sample falls due after the step that ended at s.time, under `rule`'s end.
  bool due(const bodies::Bodies& s, const StepRule& rule) const;
  void sample(const bodies::Bodies& s);

  // Per body of the state: the verdict on its series if it moved in z at t = 0, else nullopt.
  std::vector<std::optional<metrics::Verdict>> verdicts() const;
  // Whether some moving body's verdict, were the run to end now, is undecided.
  bool undecided() const;

  // The series so far, in a checkpoint (checkpoint/archive.hpp).
  template <class Archive>
  void fields(Archive& a) {
    a("verdict/count", count_), a("verdict/next", next_);
    std::vector<std::array<double, 3>> samples(ring_.size());
    for (std::size_t k = 0; k < ring_.size(); ++k)
      samples[k] = {ring_[k].time, ring_[k].separation_velocity, ring_[k].bonded_area};
    a("verdict/samples", samples);
    if constexpr (Archive::kReading)
      for (std::size_t k = 0; k < ring_.size(); ++k)
        ring_[k] = {samples[k][0], samples[k][1], samples[k][2]};
    schedule_.fields(a, "verdict/next_sample");
  }

 private:
  metrics::Verdict verdict(std::size_t k) const;

  metrics::VerdictRule rule_;
  double interval_;
  std::size_t bodies_;
  std::vector<std::size_t> moving_, resting_;
  std::vector<double> away_;  // per moving body, the sign of z moving away: -sign(v0_z)
  std::size_t capacity_;      // samples per moving body
  std::size_t count_ = 0, next_ = 0;
  std::vector<metrics::VerdictSample> ring_;  // capacity_ per moving body, in their order
  Schedule schedule_;
};

}  // namespace coldspray::run
