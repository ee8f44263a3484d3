// A run's outputs in its folder, written as it goes: case.resolved.yaml, history.csv,
// contact.csv, probes.csv, snapshots/*.vtu with snapshots.pvd, and at the end summary.json with
// the verdict on the series it sampled (run/verdict_series.hpp). run_case keeps one; a bond
// family keeps one per member (run/bond_family.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

#include "bodies/bodies.hpp"
#include "case/case.hpp"
#include "core/error.hpp"
#include "io/appended_file.hpp"
#include "io/vtu.hpp"
#include "run/checkpoint_policy.hpp"
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
  // tables' headers; `s` is the state at t = 0. With io::Opening::Resume, a restarted run's
  // recorder: the folder and its tables are left as they are for fields() to cut back to its
  // checkpoint.
  Recorder(const case_file::Case& c, const bodies::Bodies& s, std::filesystem::path out,
           io::Opening opening = io::Opening::Create);

  // At t = 0: the first rows and the first snapshot.
  void start(const bodies::Bodies& s);
  // Whether the fault checks, rows or a snapshot fall due after the step that ended at s.time.
  bool due(const bodies::Bodies& s, bool last) const;
  // After a step: the fault checks (run/fault_checks.hpp, every kFaultCheckStride steps and on
  // the `last`), which throw RunFault, then the rows and the snapshot due (rows always on the
  // `last` step; its snapshot is finish()'s).
  void after_step(const bodies::Bodies& s, bool last);
  // The rows at s.time, unless they were written at it: the tables of a run that stops early
  // end at the time it stopped.
  void write_last_rows(const bodies::Bodies& s);
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
  // The last snapshot, and summary.json with `status` ("ok", "fault: ..." or "interrupted").
  Summary finish(const bodies::Bodies& s, const std::string& status);
  // The fault path, wherever a run stops on `fault` (run_to_end, a bond family's trunk): the
  // rows at the fault time if the tables do not end there yet, the last snapshot and the summary
  // with the fault as status, each tried on its own; then throws the RunFault naming the folder
  // and, if some of them could not be written (a full disk), why.
  [[noreturn]] void end_with_fault(const bodies::Bodies& s, const RunFault& fault);
  // The same on SIGINT or SIGTERM (run/interrupt.hpp): the rows at the time it stopped, the last
  // snapshot and the summary with status "interrupted"; then throws Interrupted.
  [[noreturn]] void end_interrupted(const bodies::Bodies& s, int signal);

  // The command end_interrupted() names to continue the run (empty: `coldspray run --restart
  // FOLDER`).
  void continue_with(std::string command) { restart_command_ = std::move(command); }

  const std::filesystem::path& folder() const { return out_; }
  // The case as case.resolved.yaml has it (what a checkpoint restarts from).
  const std::string& resolved_case() const { return resolved_case_; }
  CheckpointPolicy& checkpoints() { return checkpoints_; }

  // This run's id (run/run_id.hpp): drawn for a new run, read from the folder for a restarted
  // one.
  const std::string& run_id() const { return run_id_; }

  // The recorder's progress in a checkpoint (checkpoint/archive.hpp): its schedules, the
  // verdict's series, the summary's counters, the snapshots listed in snapshots.pvd and the
  // tables' lengths. Reading only takes them in: resume() then applies them to the folder.
  template <class Archive>
  void fields(Archive& a) {
    history_due_.fields(a, "recorder/history_due");
    snapshot_due_.fields(a, "recorder/snapshot_due");
    checkpoints_.fields(a);
    verdict_.fields(a);
    a("recorder/wall_seconds", summary_.wall_seconds);
    a("recorder/extensions", summary_.extensions);
    a("recorder/shared_steps", summary_.shared_steps);
    if constexpr (!Archive::kReading) {
      resumed_.times = pvd_.times();
      resumed_.files = join_lines(pvd_.files());
      resumed_.lengths.clear();
      for (const io::AppendedFile* t : tables()) {
        t->sync();
        resumed_.lengths.push_back(t->length());
      }
    }
    a("recorder/snapshots/times", resumed_.times);
    a("recorder/snapshots/files", resumed_.files);
    a("recorder/table_lengths", resumed_.lengths);
  }
  // After a checkpoint was read: checks that every table is there and can be cut back to the
  // length the checkpoint recorded (InputError naming the table, before anything is changed),
  // then cuts them, removes the snapshots written since (or by an earlier run in the folder)
  // and what writes killed midway left: the restarted run writes them again.
  void resume();

 private:
  // The fault checks (every kFaultCheckStride steps and on the last), rows (always on the last
  // step) and a snapshot (never on it: finish() writes that one).
  struct Due {
    bool checks, rows, snapshot;
  };
  Due falling_due(const bodies::Bodies& s, bool last) const;
  Summary write_summary(const bodies::Bodies& s, const std::string& status);
  void rows(const bodies::Bodies& s, const metrics::EnergyBudget& e);
  void snapshot(const bodies::Bodies& s);
  std::vector<const io::AppendedFile*> tables() const;
  void remove_unlisted_snapshots() const;
  static std::string join_lines(const std::vector<std::string>& lines);
  static std::vector<std::string> split_lines(const std::string& text);

  // What a checkpoint records of the folder (fields()).
  struct FolderProgress {
    std::vector<double> times;            // s; the snapshots listed in snapshots.pvd
    std::string files;                    // their files, a line each
    std::vector<std::uintmax_t> lengths;  // bytes; of tables()
  };

  std::filesystem::path out_;
  std::string resolved_case_;
  std::string run_id_;
  std::string restart_command_;
  FolderProgress resumed_;
  double snapshot_interval_;
  HistoryWriter history_;
  ContactHistoryWriter contact_history_;
  ProbeWriter probes_;
  io::PvdCollection pvd_;
  Schedule history_due_, snapshot_due_;
  VerdictSeries verdict_;
  CheckpointPolicy checkpoints_;
  Summary summary_;
  FaultChecks checks_;
  double last_row_time_ = -1.0;  // s; before t = 0 until the first rows
};

}  // namespace coldspray::run
