// The validator of options that set a number of OpenMP threads (--threads, --threads-per-job):
// from 1 to the processors of this machine. Each thread reserves its stack and per-thread work
// buffers at set-up, so an absurd count (--threads 100000) exhausted the address space and
// crashed; more threads than processors never run faster (docs/reliability.md).
#pragma once

#include <CLI/CLI.hpp>

namespace coldspray::cli {

CLI::Validator machine_threads();

}  // namespace coldspray::cli
