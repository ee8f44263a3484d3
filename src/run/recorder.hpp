// A run's outputs in its folder, written as it goes: case.resolved.yaml, history.csv,
// contact.csv, probes.csv, snapshots/*.vtu with snapshots.pvd, and at the end summary.json with
// the verdict on the series it sampled (run/verdict_series.hpp). run_case keeps one; a bond
// family keeps one per member (run/bond_family.hpp).
#pragma once

#include <filesystem>
#include <string>

#include "bodies/bodies.hpp"
#include "case/case.hpp"
#include "core/error.hpp"
#include "io/vtu.hpp"
#include "run/contact_history.hpp"
#include "run/fault_checks.hpp"
#include "run/history.hpp"
#include "run/probes.hpp"
#include "run/schedule.hpp"
#include "run/step_rule.hpp"
#include "run/summary.hpp"
#include "run/verdict_series.hpp"

namespace coldspray::run {

class Recorder {
 public:
  // Creates the folder (InputError if it is a file, under one, or unwritable), removes a
  // previous run's results from it (run/run_folder.hpp) and writes case.resolved.yaml and the
  // tables' headers; `s` is the state at t = 0.
  Recorder(const case_file::Case& c, const bodies::Bodies& s, std::filesystem::path out);

  // At t = 0: the first rows and the first snapshot.
  void start(const bodies::Bodies& s);
  // Whether the fault checks, rows or a snapshot fall due after the step that ended at s.time.
  bool due(const bodies::Bodies& s, bool last) const;
  // After a step: the fault checks (run/fault_checks.hpp, every kFaultCheckStride steps and on
  // the `last`), which throw RunFault, then the rows and the snapshot due (rows always on the
  // `last` step; its snapshot is finish()'s).
  void after_step(const bodies::Bodies& s, bool last);
  // The verdict's series: whether a sample falls due after the step that ended at s.time under
  // `rule`'s end, and taking it.
  bool sample_due(const bodies::Bodies& s, const StepRule& rule) const {
    return verdict_.due(s, rule);
  }
  void sample(const bodies::Bodies& s) { verdict_.sample(s); }
  // Whether the verdict, were the run to end now, is undecided; and that the run was extended by
  // a window because it was.
  bool undecided() const { return verdict_.undecided(); }
  void add_extension() { ++summary_.extensions; }
  // Wall time spent on the run, and how many of its steps it shared with other runs.
  void add_wall(double seconds) { summary_.wall_seconds += seconds; }
  void add_shared_step() { ++summary_.shared_steps; }
  // The last snapshot, and summary.json with `status` ("ok" or "fault: ...").
  Summary finish(const bodies::Bodies& s, const std::string& status);
  // The fault path, wherever a run stops on `fault` (run_to_end, a bond family's trunk): the
  // rows at the fault time if the tables do not end there yet, the last snapshot and the summary
  // with the fault as status; then throws the RunFault naming the folder.
  [[noreturn]] void end_with_fault(const bodies::Bodies& s, const RunFault& fault);

  const std::filesystem::path& folder() const { return out_; }

 private:
  // The fault checks (every kFaultCheckStride steps and on the last), rows (always on the last
  // step) and a snapshot (never on it: finish() writes that one).
  struct Due {
    bool checks, rows, snapshot;
  };
  Due falling_due(const bodies::Bodies& s, bool last) const;
  void rows(const bodies::Bodies& s, const metrics::EnergyBudget& e);
  void snapshot(const bodies::Bodies& s);

  std::filesystem::path out_;
  double snapshot_interval_;
  HistoryWriter history_;
  ContactHistoryWriter contact_history_;
  ProbeWriter probes_;
  io::PvdCollection pvd_;
  Schedule history_due_, snapshot_due_;
  VerdictSeries verdict_;
  Summary summary_;
  FaultChecks checks_;
  double last_row_time_ = -1.0;  // s; before t = 0 until the first rows
};

}  // namespace coldspray::run
