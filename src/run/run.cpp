#include "run/run.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <iostream>
#include <string>

#include "core/error.hpp"
#include "mpm/stepper.hpp"
#include "pd/stepper.hpp"

namespace coldspray::run {

namespace {

using Clock = std::chrono::steady_clock;

// The progress line. Its ETA extrapolates the rate of the steps measured since the first one
// ended, not the first step's: that one also pays for first touches of memory and caches. Until
// a later step is measured the ETA says "--".
class Progress {
 public:
  explicit Progress(bool enabled) : enabled_(enabled), tty_(isatty(STDERR_FILENO) != 0) {}
  void report(const bodies::Bodies& s, double end, double wall, bool last) {
    if (!enabled_) return;
    if (!measuring_) {
      measuring_ = true;
      from_ = {wall, s.time};
    }
    const double interval = tty_ ? 0.5 : 10.0;
    if (!last && wall - last_wall_ < interval) return;
    last_wall_ = wall;
    const double fraction = s.time / end;
    const double simulated = s.time - from_.time;
    const std::string eta =
        last ? "0 s"
        : simulated > 0.0
            ? fmt::format("{:.0f} s", (wall - from_.wall) / simulated * (end - s.time))
            : "--";
    std::cerr << fmt::format("{}t = {:.3f} ns ({:.0f}%)  step {}  dt {:.3g} s  ETA {}{}",
                             tty_ ? "\r" : "", s.time * 1e9, 100.0 * fraction, s.step, s.dt, eta,
                             tty_ && !last ? "   " : "\n");
  }

 private:
  struct Mark {
    double wall, time;
  };
  bool enabled_, tty_;
  double last_wall_ = -1e30;
  bool measuring_ = false;  // from_ is set: the end of the first step reported
  Mark from_{0.0, 0.0};
};

// One step of the MPM: from its start, or from the contact decision of a copied run.
void advance(mpm::State& s, const StepRule& rule, ResumeAt resume) {
  if (resume == ResumeAt::StepStart) {
    s.dt = rule.next_dt(s);
    mpm::step_to_contact(s);
  }
  mpm::step_from_contact(s);
}

// One step of peridynamics (it has no contact decision to resume at).
void advance(pd::State& s, const StepRule& rule, ResumeAt) {
  s.dt = rule.next_dt(s);
  pd::step(s);
}

}  // namespace

Summary run_case(const case_file::Case& c, const RunOptions& options) {
  SolverState state = build_solver_state(c);  // InputError before anything is written
  return std::visit(
      [&](auto& s) {
        const auto begin = Clock::now();
        Recorder rec(c, s, options.out_dir);
        rec.start(s);
        rec.add_wall(std::chrono::duration<double>(Clock::now() - begin).count());
        return run_to_end(s, StepRule(c, s), rec, options.progress);
      },
      state);
}

template <class State>
Summary run_to_end(State& s, StepRule rule, Recorder& rec, bool progress_line, ResumeAt resume) {
  Progress progress(progress_line);
  const auto start = Clock::now();
  auto wall = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };
  double recorded = 0.0;  // of wall(), already added to rec
  auto account = [&] {
    const double now = wall();
    rec.add_wall(now - recorded);
    recorded = now;
  };
  try {
    while (!rule.finished(s)) {
      advance(s, rule, resume);
      resume = ResumeAt::StepStart;
      if (rec.sample_due(s, rule)) rec.sample(s);
      if (rule.finished(s) && rec.undecided() && rule.extend()) rec.add_extension();
      const bool last = rule.finished(s);
      rec.after_step(s, last);
      account();
      progress.report(s, rule.end, wall(), last);
    }
  } catch (const RunFault& fault) {
    account();
    rec.finish(s, fmt::format("fault: {}", fault.what()));
    throw RunFault(
        fmt::format("{} (last snapshot and summary in {})", fault.what(), rec.folder().string()));
  }
  account();
  return rec.finish(s, "ok");
}

template Summary run_to_end(mpm::State&, StepRule, Recorder&, bool, ResumeAt);
template Summary run_to_end(pd::State&, StepRule, Recorder&, bool, ResumeAt);

}  // namespace coldspray::run
