// The validator of options that set a number of OpenMP threads (--threads, --threads-per-job):
// from 1 to the processors of this machine: more threads than processors only share them, and an
// absurd count (--threads 100000) segfaulted (docs/reliability.md).
#pragma once

#include <CLI/CLI.hpp>

namespace coldspray::cli {

CLI::Validator machine_threads();

}  // namespace coldspray::cli
