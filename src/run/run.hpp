// Running a case: the one library entry point that the CLI and the studies call.
#pragma once

#include <filesystem>
#include <memory>
#include <string>

#include "case/case.hpp"
#include "io/folder_lock.hpp"
#include "run/recorder.hpp"
#include "run/solver.hpp"
#include "run/step_rule.hpp"
#include "run/summary.hpp"

namespace coldspray::run {

struct RunOptions {
  std::filesystem::path out_dir;  // created if missing
  bool progress = true;           // a progress line on stderr
  // A checkpoint of this case (run/checkpoints.hpp) to continue from, in out_dir, the run
  // folder that wrote it; empty: from t = 0.
  std::filesystem::path restart_from;
  // A checkpoint whose state (of another case with the same bodies) this case starts from, at
  // t = 0 (run/checkpoints.hpp, load_initial_state); empty: the case's own initial state.
  std::filesystem::path initial_state;
  // The command an interrupted run tells the user to continue it with; empty: `coldspray run
  // --restart OUT_DIR`.
  std::string restart_command;
  // InputError if out_dir holds a previous run's results (the command line's guard, off with
  // --overwrite; a restart continues its own); otherwise the run replaces them.
  bool refuse_previous_results = false;
  // out_dir's lock (io/folder_lock.hpp) if the caller took it already (a restart, before it read
  // the checkpoint); else run_case takes it once the case is set up.
  std::shared_ptr<io::FolderLock> lock;
};

// Runs the case and writes its results into options.out_dir: case.resolved.yaml, summary.json,
// history.csv, contact.csv, probes.csv (with probes), snapshots/*.vtu and snapshots.pvd, and
// checkpoints/step_*.h5 as output.checkpoint_* asks and at the end. Throws InputError before
// writing anything if the case's geometry is invalid, and before changing the folder if another
// process holds it or it holds a previous run's results that options refuse; on a fault during the
// run, writes a last snapshot, a checkpoint and a summary with the fault as status, then throws
// RunFault; on SIGINT or SIGTERM (run/interrupt.hpp), a checkpoint, the last rows and a summary
// with status "interrupted", then throws Interrupted.
Summary run_case(const case_file::Case& c, const RunOptions& options);

// Where a run picks up: at the start of a step, or, in MPM, halfway through one, at the contact
// decision (mpm::step_from_contact next), as a bond family's branch does.
enum class ResumeAt { StepStart, Contact };

// run_case's loop, for the state of any solver (run/solver.hpp): steps `s` to the rule's end
// time, recording each step in `rec`, extending the run by a verdict window while the verdict is
// undecided and the rule allows (docs/bonding.md), then writes the last snapshot and the summary.
// On a fault, the same with the fault as status, then throws RunFault naming the folder.
template <class State>
Summary run_to_end(State& s, StepRule rule, Recorder& rec, bool progress,
                   ResumeAt resume = ResumeAt::StepStart);

}  // namespace coldspray::run
