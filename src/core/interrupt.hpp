// SIGINT and SIGTERM (Ctrl-C, a batch system's time limit) only set a flag; the work in progress
// reads it and stops by throwing Interrupted, which the command line turns into exit status
// 128 + the signal (130, 143) after saying where it stopped (docs/reliability.md). A run stops
// after its step with a checkpoint (run/run.cpp); the set-up before it (placing a deposit's
// particles, seeding bodies, building families) stops where it stands, before anything is
// written. Here in core/, below the layers that set up a run (bodies/, geometry/, pd/, mpm/),
// which may read the flag but not include run/.
#pragma once

#include <stdexcept>
#include <string>
#include <string_view>

namespace coldspray {

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

// Throws Interrupted, "interrupted during set-up (PHASE); nothing was written", if a signal is
// pending. For the loops of a run's set-up, before its output folder is prepared: a load of the
// flag, cheap enough to call every few thousand items.
void stop_set_up_if_interrupted(std::string_view phase);

}  // namespace coldspray
