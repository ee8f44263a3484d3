#include "run/recorder.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <algorithm>
#include <functional>
#include <sstream>

#include "case/load.hpp"
#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "metrics/body_metrics.hpp"
#include "metrics/energy.hpp"
#include "run/interrupt.hpp"
#include "run/run_folder.hpp"
#include "run/run_id.hpp"
#include "run/snapshot.hpp"

namespace coldspray::run {

namespace {

std::string resolved_text(const case_file::Case& c) {
  std::ostringstream text;
  case_file::write_resolved(c, text);
  return text.str();
}

std::filesystem::path prepared(const std::filesystem::path& out, const std::string& resolved_case,
                               const std::string& run_id, io::Opening opening) {
  if (opening == io::Opening::Resume) return out;
  prepare_run_folder(out);
  io::write_atomically(out / "case.resolved.yaml", [&](std::ostream& os) { os << resolved_case; });
  write_run_id(out, run_id);
  return out;
}

}  // namespace

Recorder::Recorder(const case_file::Case& c, const bodies::Bodies& s, std::filesystem::path out,
                   io::Opening opening)
    : out_(std::move(out)),
      resolved_case_(resolved_text(c)),
      run_id_(opening == io::Opening::Resume ? read_run_id(out_) : new_run_id()),
      snapshot_interval_(c.output.snapshot_interval),
      history_(s, prepared(out_, resolved_case_, run_id_, opening) / "history.csv", opening),
      contact_history_(out_ / "contact.csv", opening),
      probes_(c.output.probes, s, out_ / "probes.csv", opening),
      pvd_(out_ / "snapshots.pvd"),
      history_due_(c.output.history_interval),
      snapshot_due_(c.output.snapshot_interval),
      verdict_(c.metrics, s),
      checkpoints_(c.output),
      checks_(metrics::energy_budget(s).total(),
              c.contact.peridynamics.model != case_file::ContactModel::Repulsive ||
                  c.grip.has_value()) {
  summary_.threads = omp_get_max_threads();
  summary_.particles = s.points.size();
  summary_.discretisation = s.discretisation;
  summary_.total_energy_initial = checks_.initial_total();
}

void Recorder::start(const bodies::Bodies& s) {
  after_step(s, /*last=*/true);  // the rows at t = 0, always
  verdict_.sample(s);            // so that a run shorter than the window is read from its start
  snapshot_due_.done(0.0);
  snapshot(s);
}

Recorder::Due Recorder::falling_due(const bodies::Bodies& s, bool last) const {
  return {FaultChecks::due(s, last), last || history_due_.due(s.time),
          !last && snapshot_interval_ > 0.0 && snapshot_due_.due(s.time)};
}

bool Recorder::due(const bodies::Bodies& s, bool last) const {
  const Due d = falling_due(s, last);
  return d.checks || d.rows || d.snapshot;
}

void Recorder::after_step(const bodies::Bodies& s, bool last) {
  const Due d = falling_due(s, last);
  if (d.checks || d.rows) {
    const metrics::EnergyBudget e = metrics::energy_budget(s);
    if (d.checks) checks_.check(s, e);
    if (d.rows) rows(s, e);
  }
  if (d.snapshot) {
    snapshot_due_.done(s.time);
    snapshot(s);
  }
}

void Recorder::rows(const bodies::Bodies& s, const metrics::EnergyBudget& e) {
  history_due_.done(s.time);
  history_.record(s.time, e, metrics::body_metrics(s, metrics::SplatExtent::Skipped));
  contact_history_.record(s);
  probes_.record(s);
  last_row_time_ = s.time;
}

void Recorder::write_last_rows(const bodies::Bodies& s) {
  if (last_row_time_ != s.time) rows(s, metrics::energy_budget(s));
}

void Recorder::snapshot(const bodies::Bodies& s) {
  const std::string name = fmt::format("snapshots/step_{:08d}.vtu", s.step);
  write_snapshot(s, out_ / name);
  pvd_.add(s.time, name);
}

Summary Recorder::finish(const bodies::Bodies& s, const std::string& status) {
  snapshot(s);
  return write_summary(s, status);
}

Summary Recorder::write_summary(const bodies::Bodies& s, const std::string& status) {
  summary_.status = status;
  summary_.steps = s.step;
  summary_.time = s.time;
  summary_.last_dt = s.dt;
  summary_.particle_steps_per_second =
      summary_.wall_seconds > 0.0 ? static_cast<double>(s.step) *
                                        static_cast<double>(s.points.size()) / summary_.wall_seconds
                                  : 0.0;
  summary_.energy = metrics::energy_budget(s);
  summary_.bodies = metrics::body_metrics(s, metrics::SplatExtent::Measured);
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

void Recorder::resume() {
  const std::vector<const io::AppendedFile*> t = tables();
  if (t.size() != resumed_.lengths.size())
    throw InputError(out_.string(), "",
                     fmt::format("holds {} tables where its checkpoint recorded {}", t.size(),
                                 resumed_.lengths.size()));
  for (std::size_t k = 0; k < t.size(); ++k) t[k]->check_resumable(resumed_.lengths[k]);
  const std::vector<std::string> files = split_lines(resumed_.files);
  if (files.size() != resumed_.times.size())
    throw InputError(out_.string(), "recorder/snapshots",
                     "lists snapshot times and files that do not pair up");
  // Checked: from here on the folder changes.
  pvd_.assign(resumed_.times, files);
  remove_unlisted_snapshots();
  for (std::size_t k = 0; k < t.size(); ++k) t[k]->cut_to(resumed_.lengths[k]);
  remove_interrupted_writes(out_);
}

void Recorder::remove_unlisted_snapshots() const {
  const std::vector<std::string> listed = pvd_.files();
  for (const std::filesystem::path& file : step_files(out_ / "snapshots", ".vtu"))
    if (std::find(listed.begin(), listed.end(), "snapshots/" + file.filename().string()) ==
        listed.end())
      std::filesystem::remove(file);
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

void Recorder::end_with_fault(const bodies::Bodies& s, const RunFault& fault) {
  // Each of the last results on its own: the fault may be a full disk, where the snapshot fails
  // but the summary, or the rows, still fit; the message keeps the fault and says what is lost.
  std::vector<std::string> lost;
  const auto attempt = [&](const std::function<void()>& write) {
    try {
      write();
    } catch (const RunFault& e) {
      lost.push_back(e.what());
    }
  };
  attempt([&] { write_last_rows(s); });
  attempt([&] { snapshot(s); });
  attempt([&] { write_summary(s, fmt::format("fault: {}", fault.what())); });
  if (lost.empty())
    throw RunFault(
        fmt::format("{} (last snapshot and summary in {})", fault.what(), out_.string()));
  std::string unwritten;
  for (const std::string& e : lost) unwritten += "; " + e;
  throw RunFault(fmt::format("{} (in {}; its last results could not all be written{})",
                             fault.what(), out_.string(), unwritten));
}

void Recorder::end_interrupted(const bodies::Bodies& s, int signal) {
  write_last_rows(s);
  finish(s, "interrupted");
  throw Interrupted(
      signal,
      fmt::format("interrupted at t = {:.6g} ns, step {}; continue with: {}", s.time * 1e9, s.step,
                  restart_command_.empty() ? "coldspray run --restart " + out_.string()
                                           : restart_command_));
}

}  // namespace coldspray::run
