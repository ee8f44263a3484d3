// Runs the built `coldspray` binary for command-line tests.
#pragma once

#include <string>

namespace coldspray::testing {

struct CommandResult {
  int status = -1;     // exit status
  std::string output;  // stdout and stderr, interleaved
};

// Runs `coldspray ARGS` through the shell in `workdir` (default: a fresh temporary folder).
CommandResult run_coldspray(const std::string& args, const std::string& workdir = "");

// Whether the command printed `part`.
inline bool has(const CommandResult& r, const std::string& part) {
  return r.output.find(part) != std::string::npos;
}

}  // namespace coldspray::testing
