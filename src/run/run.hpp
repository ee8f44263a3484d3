// Running a case: the one library entry point that the CLI and the studies call.
#pragma once

#include <filesystem>

#include "case/case.hpp"
#include "run/recorder.hpp"
#include "run/solver.hpp"
#include "run/step_rule.hpp"
#include "run/summary.hpp"

namespace coldspray::run {

struct RunOptions {
  std::filesystem::path out_dir;  // created if missing
  bool progress = true;           // a progress line on stderr
};

// Runs the case and writes its results into options.out_dir: case.resolved.yaml, summary.json,
// history.csv, probes.csv (with probes), snapshots/*.vtu and snapshots.pvd. Throws InputError
// before writing anything if the case's geometry is invalid; on a fault during the run, writes
// a last snapshot and a summary with the fault as status, then throws RunFault.
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
