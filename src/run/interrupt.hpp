// SIGINT and SIGTERM (Ctrl-C, a batch system's time limit): the run in progress finishes its
// step, writes a checkpoint, the tables' last rows and summary.json with status "interrupted",
// and throws Interrupted, which the command line turns into exit status 128 + the signal
// (130, 143) after saying where the run stopped (docs/reliability.md).
#pragma once

#include <stdexcept>
#include <string>

namespace coldspray::run {

class Interrupted : public std::runtime_error {
 public:
  Interrupted(int signal, const std::string& what) : std::runtime_error(what), signal_(signal) {}
  int signal() const { return signal_; }

 private:
  int signal_;
};

// Installs the handlers: from then on, SIGINT and SIGTERM only set a flag that runs read.
void catch_interrupts();
// The signal received since catch_interrupts(), 0 if none.
int pending_interrupt();

}  // namespace coldspray::run
