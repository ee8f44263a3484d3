// A run's folder: the files a run writes there (run/recorder.hpp), whether a folder holds a
// previous run's, and clearing them so that a new run's results never sit beside an old run's
// snapshots that its snapshots.pvd does not list (docs/reliability.md, "Output folders").
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>
#include <vector>

namespace coldspray::run {

// The files a run numbers by step in `dir`, step_NNNNNNNN`extension` (snapshots/*.vtu,
// checkpoints/*.h5), by step.
std::vector<std::filesystem::path> step_files(const std::filesystem::path& dir,
                                              std::string_view extension);

// The first file or folder of a run's results in `folder`, if any (summary.json, history.csv,
// snapshots.pvd, a snapshot, ...): the folder holds a previous run's results.
std::optional<std::filesystem::path> previous_run_result(const std::filesystem::path& folder);

// Removes the temporary files of writes killed midway (io::remove_stale_temporaries) from a run
// folder and its snapshots and checkpoints.
void remove_interrupted_writes(const std::filesystem::path& folder);

// Makes `folder` a writable folder (io/make_output_folder: InputError if it cannot be) and removes
// a previous run's results and interrupted writes from it, leaving any other file alone.
void prepare_run_folder(const std::filesystem::path& folder);

}  // namespace coldspray::run
