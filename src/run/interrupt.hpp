// The interrupt flag and Interrupted (core/interrupt.hpp), under the names the run and the
// studies use: a run stops at SIGINT or SIGTERM after its step, writes a checkpoint, the
// tables' last rows and summary.json with status "interrupted", and throws Interrupted
// (docs/reliability.md).
#pragma once

#include "core/interrupt.hpp"

namespace coldspray::run {

using coldspray::catch_interrupts;
using coldspray::Interrupted;
using coldspray::pending_interrupt;

}  // namespace coldspray::run
