#include "core/interrupt.hpp"

#include <fmt/format.h>

#include <csignal>

namespace coldspray {

namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void note_signal(int signal) { received = signal; }

}  // namespace

void catch_interrupts() {
  struct sigaction action {};
  action.sa_handler = note_signal;
  // A second signal ends the program at once: the way out of a checkpoint that takes too long,
  // or of work that does not read the flag.
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int pending_interrupt() { return received; }

void stop_set_up_if_interrupted(std::string_view phase) {
  if (const int signal = pending_interrupt())
    throw Interrupted(signal,
                      fmt::format("interrupted during set-up ({}); nothing was written", phase));
}

}  // namespace coldspray
