// Running many cases, each in its own folder, as `sweep`, `vcrit` and `calibrate` do: a folder
// holding summary.json is finished and is not run again (resumable); a failure is recorded in
// the folder's summary and the study goes on; cases run in parallel threads of one process.
#pragma once

#include <cstddef>
#include <exception>
#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "case/case.hpp"

namespace coldspray::studies {

// A case folder is finished once it holds summary.json (run_case writes it last; a failure is
// recorded in one too) whose status is not "interrupted" (run/interrupt.hpp). Unfinished
// folders are cleared and run again.
bool case_finished(const std::filesystem::path& folder);

// The folder's summary.json, or a discarded (null) json when it is missing or unreadable.
nlohmann::json read_summary(const std::filesystem::path& folder);

// Clears `folder`, then calls `load` (which may write notes into the folder) and runs the case
// there. An InputError, RunFault or other exception is recorded as by record_outcome; returns
// false then.
bool run_in_folder(const std::filesystem::path& folder,
                   const std::function<case_file::Case()>& load);

// How a case in `folder` ended: true for no failure; otherwise an InputError, RunFault or other
// exception is recorded as the summary's status ("input error: ...", "fault: ...", "error: ...",
// keeping the summary a RunFault's run has written) and false returned. A run::Interrupted case
// is left unfinished (false, nothing recorded).
bool record_outcome(const std::filesystem::path& folder, const std::exception_ptr& failure);

// The indices of `folders` that this rank runs (i % ranks == rank) and that are not finished;
// `skipped` counts this rank's finished ones.
std::vector<std::size_t> pending_folders(const std::vector<std::filesystem::path>& folders,
                                         int rank, int ranks, std::size_t& skipped);

// A CSV field, quoted when it holds a comma, a quote or a newline.
std::string csv_field(const std::string& text);
// A number in a study's CSV: 10 significant digits, "nan" for NaN.
std::string csv_number(double x);

// Calls body(k) for every k in [0, count), on min(jobs, count) threads of this process (this
// one included), each set to `threads_per_job` OpenMP threads (0: the cores shared among the
// jobs). `body` must not throw. Throws run::Interrupted once all have returned if SIGINT or
// SIGTERM came meanwhile (the cases not started then are skipped by run_in_folder).
void run_parallel(std::size_t count, int jobs, int threads_per_job,
                  const std::function<void(std::size_t)>& body);

// After a study's cases: throws run::Interrupted if SIGINT or SIGTERM came meanwhile.
void throw_if_interrupted();

}  // namespace coldspray::studies
