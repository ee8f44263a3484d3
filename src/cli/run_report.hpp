// What `run` and `impact` share: the options that say where and how a case runs, and running a
// validated case with its summary printed.
#pragma once

#include <CLI/CLI.hpp>
#include <filesystem>
#include <iosfwd>
#include <memory>
#include <string>
#include <vector>

#include "case/case.hpp"
#include "case/load.hpp"
#include "io/folder_lock.hpp"
#include "run/summary.hpp"

namespace coldspray::cli {

struct RunFlags {
  std::string out_dir;  // default out/NAME
  std::vector<std::string> sets;
  int threads = 0;  // 0: all cores
  bool quiet = false;
  // `run --restart`: the checkpoint the run continues from, in its own folder (out_dir).
  std::filesystem::path restart_from;
  // `run --initial-state`: a checkpoint whose state the case starts from.
  std::filesystem::path initial_state;
  bool overwrite = false;  // run into a folder that holds a previous run's results
  // The command that continues an interrupted run (run::RunOptions::restart_command).
  std::string restart_command;
  // The run folder's lock (io/folder_lock.hpp), once restart_case took it.
  std::shared_ptr<io::FolderLock> lock;
};

// --out, --overwrite, --set, --threads and --quiet on a subcommand; `flags` must outlive the
// parse.
void add_run_flags(CLI::App& sub, RunFlags& flags);

// The --set texts as overrides; InputError for one that is not KEY=VALUE.
std::vector<case_file::Override> parse_overrides(const std::vector<std::string>& sets);

// `--restart RUN_OR_CHECKPOINT`: the run continues from that checkpoint (a run folder's latest),
// in its own folder, as the case the checkpoint holds; sets flags.restart_from and out_dir and
// takes the folder's lock. InputError if there is no checkpoint, another process holds the
// folder, or with --set or --out, which a restart cannot apply.
case_file::Case restart_case(const std::string& run_or_checkpoint, RunFlags& flags);

// Where a case runs: flags.out_dir, or out/NAME.
std::filesystem::path run_folder(const case_file::Case& c, const RunFlags& flags);

struct Report {
  run::Summary summary;
  std::filesystem::path out_dir;
};

// Prints the case, runs it into flags.out_dir (or out/NAME) and prints the steps, the energy
// budget and each body's motion; RunFault and InputError pass through (run::run_case: the
// folder is InputError if another process holds it, or if it holds a previous run's results
// unless flags.overwrite, which replaces them).
Report run_and_report(const case_file::Case& c, const RunFlags& flags, std::ostream& out);

// "results in DIR/ (...)": the last line of `run` and `impact`.
void print_results_location(const std::filesystem::path& out_dir, std::ostream& out);

}  // namespace coldspray::cli
