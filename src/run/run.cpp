#include "run/run.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <iostream>
#include <string>

#include "bodies/grip.hpp"
#include "core/error.hpp"
#include "core/interrupt.hpp"
#include "io/output_folder.hpp"
#include "mpm/stepper.hpp"
#include "pd/stepper.hpp"
#include "run/checkpoints.hpp"
#include "run/interrupt.hpp"
#include "run/run_folder.hpp"

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

// Writes a checkpoint where the run stands; at a fault, one that fails to write must not hide
// the fault, so it is reported on stderr instead.
template <class State>
void checkpoint_now(State& s, Recorder& rec, StepRule& rule, double wall, bool at_fault = false) {
  try {
    write_checkpoint(s, rec, rule);
    rec.checkpoints().done(s.time, wall);
  } catch (const std::exception& e) {
    if (!at_fault) throw;
    std::cerr << fmt::format("warning: no checkpoint at the fault: {}\n", e.what());
  }
}

// A case with a grip (bodies/grip.hpp) starts at rest with its grip taken, from its own initial
// state or a checkpoint's.
void take_grip(bodies::Bodies& s, const case_file::Case& c) {
  if (c.grip) bodies::take_grip(s, *c.grip);
}

// The folder for a run, held: created and locked (if the caller did not) and, for a new run,
// free of a previous run's results if the options refuse them.
std::shared_ptr<io::FolderLock> hold_folder(const RunOptions& options) {
  std::shared_ptr<io::FolderLock> lock = options.lock;
  if (!lock) {
    io::make_output_folder(options.out_dir);
    lock = std::make_shared<io::FolderLock>(options.out_dir, "--out");
  }
  if (const auto previous = previous_run_result(options.out_dir);
      previous && options.refuse_previous_results && options.restart_from.empty())
    throw InputError("--out", "",
                     fmt::format("'{}' holds a previous run's results ({}); pass --overwrite to "
                                 "replace them, or choose another folder",
                                 options.out_dir.string(), previous->string()));
  return lock;
}

}  // namespace

Summary run_case(const case_file::Case& c, const RunOptions& options) {
  SolverState state = build_solver_state(c);  // InputError before anything is written
  // A signal after the set-up's last check stops here too, before the folder is touched.
  stop_set_up_if_interrupted("the state was built");
  std::shared_ptr<io::FolderLock> lock;
  return std::visit(
      [&](auto& s) {
        const auto begin = Clock::now();
        if (!options.restart_from.empty()) {
          // The undeformed state sets the rule's fixed dt and the recorder's t = 0 references;
          // then the checkpoint moves both, and the state, to where it was written.
          StepRule rule(c, s);
          lock = hold_folder(options);
          Recorder rec(c, s, options.out_dir, io::Opening::Resume);
          rec.continue_with(options.restart_command);
          read_checkpoint(options.restart_from, s, rec, rule);
          rec.checkpoints().enable();
          return run_to_end(s, rule, rec, options.progress);
        }
        if (!options.initial_state.empty()) load_initial_state(options.initial_state, s);
        take_grip(s, c);
        lock = hold_folder(options);
        Recorder rec(c, s, options.out_dir);
        rec.continue_with(options.restart_command);
        rec.checkpoints().enable();
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
      if (!last && rec.checkpoints().due(s.time, wall())) checkpoint_now(s, rec, rule, wall());
      if (const int signal = pending_interrupt()) {
        // The checkpoint first, so that the tables' lengths it records leave out the rows at
        // the interruption, which a restarted run does not write.
        if (rec.checkpoints().enabled()) checkpoint_now(s, rec, rule, wall());
        rec.end_interrupted(s, signal);
      }
      progress.report(s, rule.end, wall(), last);
    }
  } catch (const RunFault& fault) {
    account();
    if (rec.checkpoints().enabled()) checkpoint_now(s, rec, rule, wall(), /*at_fault=*/true);
    rec.end_with_fault(s, fault);
  }
  account();
  if (rec.checkpoints().enabled()) checkpoint_now(s, rec, rule, wall());
  return rec.finish(s, "ok");
}

template Summary run_to_end(mpm::State&, StepRule, Recorder&, bool, ResumeAt);
template Summary run_to_end(pd::State&, StepRule, Recorder&, bool, ResumeAt);

}  // namespace coldspray::run
