#include "run/recorder.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <sstream>

#include "case/load.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "metrics/body_metrics.hpp"
#include "metrics/energy.hpp"
#include "run/snapshot.hpp"

namespace coldspray::run {

namespace {

std::string resolved_text(const case_file::Case& c) {
  std::ostringstream text;
  case_file::write_resolved(c, text);
  return text.str();
}

std::filesystem::path prepared(const std::filesystem::path& out, const std::string& resolved_case,
                               io::Opening opening) {
  if (opening == io::Opening::Resume) return out;
  std::filesystem::create_directories(out / "snapshots");
  io::write_atomically(out / "case.resolved.yaml", [&](std::ostream& os) { os << resolved_case; });
  return out;
}

}  // namespace

Recorder::Recorder(const case_file::Case& c, const bodies::Bodies& s, std::filesystem::path out,
                   io::Opening opening)
    : out_(std::move(out)),
      resolved_case_(resolved_text(c)),
      snapshot_interval_(c.output.snapshot_interval),
      history_(s, prepared(out_, resolved_case_, opening) / "history.csv", opening),
      contact_history_(out_ / "contact.csv", opening),
      probes_(c.output.probes, s, out_ / "probes.csv", opening),
      pvd_(out_ / "snapshots.pvd"),
      history_due_(c.output.history_interval),
      snapshot_due_(c.output.snapshot_interval),
      verdict_(c.metrics, s),
      checkpoints_(c.output) {
  summary_.threads = omp_get_max_threads();
  summary_.particles = s.points.size();
  summary_.discretisation = s.discretisation;
  summary_.total_energy_initial = metrics::energy_budget(s).total();
}

void Recorder::start(const bodies::Bodies& s) {
  after_step(s, /*last=*/true);  // the rows at t = 0, always
  verdict_.sample(s);            // so that a run shorter than the window is read from its start
  snapshot_due_.done(0.0);
  snapshot(s);
}

Recorder::Due Recorder::falling_due(const bodies::Bodies& s, bool last) const {
  return {last || history_due_.due(s.time),
          !last && snapshot_interval_ > 0.0 && snapshot_due_.due(s.time)};
}

bool Recorder::due(const bodies::Bodies& s, bool last) const {
  const Due d = falling_due(s, last);
  return d.rows || d.snapshot;
}

void Recorder::after_step(const bodies::Bodies& s, bool last) {
  const Due d = falling_due(s, last);
  if (d.rows) {
    history_due_.done(s.time);
    const metrics::EnergyBudget e = write_rows(s);
    // (A run that starts with no energy at all, bodies at rest, has no scale to grow against.)
    if (summary_.total_energy_initial > 0.0 &&
        e.total() > (1.0 + kEnergyGrowthLimit) * summary_.total_energy_initial)
      throw RunFault(
          fmt::format("total energy grew to {:.4g} J from {:.4g} J at t = {:.6g} ns "
                      "(an instability: try a smaller solver.cfl)",
                      e.total(), summary_.total_energy_initial, s.time * 1e9));
  }
  if (d.snapshot) {
    snapshot_due_.done(s.time);
    snapshot(s);
  }
}

metrics::EnergyBudget Recorder::write_rows(const bodies::Bodies& s) {
  const metrics::EnergyBudget e = metrics::energy_budget(s);
  history_.record(s.time, e, metrics::body_metrics(s));
  contact_history_.record(s);
  probes_.record(s);
  last_rows_time_ = s.time;
  return e;
}

void Recorder::write_last_rows(const bodies::Bodies& s) {
  if (s.time != last_rows_time_) write_rows(s);
}

void Recorder::snapshot(const bodies::Bodies& s) {
  const std::string name = fmt::format("snapshots/step_{:08d}.vtu", s.step);
  write_snapshot(s, out_ / name);
  pvd_.add(s.time, name);
}

Summary Recorder::finish(const bodies::Bodies& s, const std::string& status) {
  snapshot(s);
  summary_.status = status;
  summary_.steps = s.step;
  summary_.time = s.time;
  summary_.last_dt = s.dt;
  summary_.particle_steps_per_second =
      summary_.wall_seconds > 0.0 ? static_cast<double>(s.step) *
                                        static_cast<double>(s.points.size()) / summary_.wall_seconds
                                  : 0.0;
  summary_.energy = metrics::energy_budget(s);
  summary_.bodies = metrics::body_metrics(s);
  const std::vector<std::optional<metrics::Verdict>> verdicts = verdict_.verdicts();
  for (std::size_t b = 0; b < summary_.bodies.size(); ++b) summary_.bodies[b].verdict = verdicts[b];
  write_summary_json(summary_, out_ / "summary.json");
  return summary_;
}

std::vector<const io::AppendedFile*> Recorder::tables() const {
  std::vector<const io::AppendedFile*> t{&history_.file(), &contact_history_.file()};
  if (probes_.file()) t.push_back(probes_.file());
  return t;
}

void Recorder::remove_unlisted_snapshots() const {
  const std::vector<std::string> listed = pvd_.files();
  for (const auto& entry : std::filesystem::directory_iterator(out_ / "snapshots")) {
    const std::string name = "snapshots/" + entry.path().filename().string();
    if (entry.path().extension() == ".vtu" &&
        std::find(listed.begin(), listed.end(), name) == listed.end())
      std::filesystem::remove(entry.path());
  }
}

std::string Recorder::join_lines(const std::vector<std::string>& lines) {
  std::string text;
  for (const std::string& line : lines) text += line + "\n";
  return text;
}

std::vector<std::string> Recorder::split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  return lines;
}

}  // namespace coldspray::run
