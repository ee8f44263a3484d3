// Checkpoint files of a run (docs/reliability.md, "Checkpoint and restart"): one HDF5 file per
// checkpoint, RUN/checkpoints/step_NNNNNNNN.h5, holding the format version, the solver, the
// resolved case, the run's id (run/run_id.hpp), the state's fields (checkpoint/fields.hpp), the
// recorder's progress and the step rule's end; sealed with a checksum (io/sealed_image.hpp),
// written to a temporary file, synced and renamed, so a reader (or a kill -9) never meets half
// a checkpoint, and a damaged one is refused. A restarted run continues bit for bit as the
// uninterrupted one.
#pragma once

#include <filesystem>
#include <string>

#include "case/case.hpp"
#include "run/recorder.hpp"
#include "run/step_rule.hpp"

namespace coldspray::run {

// The checkpoint format this build writes and reads. 2: PD's contact model 2 bonds and grip;
// 3: sealed with a checksum, and the run's id.
inline constexpr int kCheckpointFormat = 3;

// Writes the checkpoint of `s` (with `rec`'s and `rule`'s progress) into rec's folder, keeping
// the last CheckpointPolicy::keep() of them; returns its path.
template <class State>
std::filesystem::path write_checkpoint(State& s, Recorder& rec, StepRule& rule);

// The checkpoint a path names: a checkpoint file, or a run folder's latest (by step).
// InputError if there is none.
std::filesystem::path find_checkpoint(const std::filesystem::path& file_or_run);

// The resolved case a checkpoint holds, loaded as a case file would be (InputError naming the
// checkpoint if it is not one this build can read).
case_file::Case checkpoint_case(const std::filesystem::path& file);

// Reads a checkpoint of this case into the state set up from it, and into the recorder and
// step rule built for it, then resumes the recorder's folder (Recorder::resume). InputError
// before anything in the folder changes if the checkpoint is not this folder's run's (its run id
// and case), or a table cannot be continued.
template <class State>
void read_checkpoint(const std::filesystem::path& file, State& s, Recorder& rec, StepRule& rule);

// Starts another case from a checkpoint's state (an impacted splat to pull off, say): reads the
// points, bodies and solver fields into the state set up from that case, then sets the clock to
// t = 0, step 0. The case must have the checkpoint's solver and bodies (names, in order, each
// seeded with as many points as the checkpoint has, counting those that had left the MPM's
// grid); InputError otherwise.
template <class State>
void load_initial_state(const std::filesystem::path& file, State& s);

}  // namespace coldspray::run
