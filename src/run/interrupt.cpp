#include "run/interrupt.hpp"

#include <csignal>

namespace coldspray::run {

namespace {

volatile std::sig_atomic_t received = 0;

extern "C" void note_signal(int signal) { received = signal; }

}  // namespace

void catch_interrupts() {
  struct sigaction action {};
  action.sa_handler = note_signal;
  // A second signal ends the program at once: the way out of a set-up or a checkpoint that
  // takes too long.
  action.sa_flags = SA_RESETHAND;
  sigemptyset(&action.sa_mask);
  sigaction(SIGINT, &action, nullptr);
  sigaction(SIGTERM, &action, nullptr);
}

int pending_interrupt() { return received; }

}  // namespace coldspray::run
