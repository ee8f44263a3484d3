// Runs the built `coldspray` binary for command-line tests.
#pragma once

#include <sys/types.h>

#include <string>
#include <vector>

namespace coldspray::testing {

struct CommandResult {
  int status = -1;     // exit status
  std::string output;  // stdout and stderr, interleaved
};

// Runs `coldspray ARGS` through the shell in `workdir` (default: a fresh temporary folder).
CommandResult run_coldspray(const std::string& args, const std::string& workdir = "");

// The same with `prefix` before the binary in the shell's command line: a tool that runs it under
// a limit, such as "prlimit --fsize=2000000".
CommandResult run_coldspray_under(const std::string& prefix, const std::string& args,
                                  const std::string& workdir = "");

// Starts `coldspray ARGS...` in the background, its stdout and stderr into `output` if given;
// returns its pid.
pid_t spawn_coldspray(std::vector<std::string> args, const std::string& output = "");

// Waits for `pid` to end: its exit status, or minus the signal that ended it.
int exit_status(pid_t pid);

// Whether the command printed `part`.
inline bool has(const CommandResult& r, const std::string& part) {
  return r.output.find(part) != std::string::npos;
}

}  // namespace coldspray::testing
