#include "run/run.hpp"

#include <fmt/format.h>
#include <omp.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <iostream>

#include "case/load.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/vtu.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"
#include "run/contact_history.hpp"
#include "run/history.hpp"
#include "run/probes.hpp"
#include "run/snapshot.hpp"

namespace coldspray::run {

namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

// Times at a fixed interval: due(t) is true once per interval crossed (always, if interval 0).
class Schedule {
 public:
  explicit Schedule(double interval) : interval_(interval) {}
  bool due(double t) {
    if (interval_ <= 0.0) return true;
    if (t + 1e-9 * interval_ < next_) return false;
    while (next_ <= t + 1e-9 * interval_) next_ += interval_;
    return true;
  }

 private:
  double interval_;
  double next_ = 0.0;
};

class Progress {
 public:
  Progress(bool enabled, double end_time)
      : enabled_(enabled), tty_(isatty(STDERR_FILENO) != 0), end_(end_time) {}
  void report(const mpm::State& s, double wall, bool last) {
    if (!enabled_) return;
    const double interval = tty_ ? 0.5 : 10.0;
    if (!last && wall - last_wall_ < interval) return;
    last_wall_ = wall;
    const double fraction = s.time / end_;
    const double eta = fraction > 0.0 ? wall * (1.0 - fraction) / fraction : 0.0;
    std::cerr << fmt::format("{}t = {:.3f} ns ({:.0f}%)  step {}  dt {:.3g} s  ETA {:.0f} s{}",
                             tty_ ? "\r" : "", s.time * 1e9, 100.0 * fraction, s.step, s.dt, eta,
                             tty_ && !last ? "   " : "\n");
  }

 private:
  bool enabled_, tty_;
  double end_, last_wall_ = -1e30;
};

}  // namespace

Summary run_case(const case_file::Case& c, const RunOptions& options) {
  mpm::State s = mpm::build_state(c);  // InputError before anything is written

  const fs::path out = options.out_dir;
  fs::create_directories(out / "snapshots");
  io::write_atomically(out / "case.resolved.yaml",
                       [&](std::ostream& os) { case_file::write_resolved(c, os); });
  HistoryWriter history(s, out / "history.csv");
  ContactHistoryWriter contact_history(out / "contact.csv");
  ProbeWriter probes(c.output.probes, s, out / "probes.csv");
  io::PvdCollection pvd(out / "snapshots.pvd");
  auto snapshot = [&] {
    const std::string name = fmt::format("snapshots/step_{:08d}.vtu", s.step);
    write_snapshot(s, out / name);
    pvd.add(s.time, name);
  };

  Summary summary;
  summary.threads = omp_get_max_threads();
  summary.particles = s.points.size();
  summary.total_energy_initial = metrics::energy_budget(s).total();

  // solver.dt_scale fixes dt at that fraction of h / c of the undeformed materials (the thesis'
  // scaling of the critical step, §5.1.4); otherwise dt follows the CFL bound every step.
  const double fixed_dt =
      c.solver.dt_scale ? *c.solver.dt_scale * mpm::stable_time_step(s, 1.0) : 0.0;
  Schedule history_due(c.output.history_interval), snapshot_due(c.output.snapshot_interval);
  Progress progress(options.progress, c.solver.end_time);
  const auto start = Clock::now();
  auto wall = [&] { return std::chrono::duration<double>(Clock::now() - start).count(); };

  // History rows and probes at their interval; the energy check rides on the same budget.
  auto observe = [&](bool force) {
    if (!history_due.due(s.time) && !force) return;
    const metrics::EnergyBudget e = metrics::energy_budget(s);
    history.record(s.time, e, metrics::body_metrics(s));
    contact_history.record(s);
    probes.record(s);
    if (e.total() > (1.0 + kEnergyGrowthLimit) * summary.total_energy_initial)
      throw RunFault(
          fmt::format("total energy grew to {:.4g} J from {:.4g} J at t = {:.6g} ns "
                      "(an instability: try a smaller solver.cfl)",
                      e.total(), summary.total_energy_initial, s.time * 1e9));
  };
  auto finish = [&](const std::string& status) {
    summary.status = status;
    summary.steps = s.step;
    summary.time = s.time;
    summary.wall_seconds = wall();
    summary.last_dt = s.dt;
    summary.particle_steps_per_second =
        summary.wall_seconds > 0.0 ? static_cast<double>(s.step) *
                                         static_cast<double>(s.points.size()) / summary.wall_seconds
                                   : 0.0;
    summary.energy = metrics::energy_budget(s);
    summary.bodies = metrics::body_metrics(s);
    write_summary_json(summary, out / "summary.json");
  };

  const double end = c.solver.end_time;
  try {
    observe(true);
    snapshot_due.due(0.0);
    snapshot();
    while (s.time < end * (1.0 - 1e-12)) {
      s.dt = std::min(fixed_dt > 0.0 ? fixed_dt : mpm::stable_time_step(s, c.solver.cfl),
                      end - s.time);
      mpm::step(s);
      const bool last = s.time >= end * (1.0 - 1e-12);
      observe(last);
      if (c.output.snapshot_interval > 0.0 && snapshot_due.due(s.time) && !last) snapshot();
      progress.report(s, wall(), last);
    }
  } catch (const RunFault& fault) {
    snapshot();
    finish(fmt::format("fault: {}", fault.what()));
    throw RunFault(fmt::format("{} (last snapshot and summary in {})", fault.what(), out.string()));
  }
  snapshot();
  finish("ok");
  return summary;
}

}  // namespace coldspray::run
