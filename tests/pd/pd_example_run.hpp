// A peridynamics state built from an example case (examples/<name>, with overrides) and advanced
// by a number of steps at the case's cfl: the starting point of the PD tests that need a moving,
// deformed state.
#pragma once

#include <string>
#include <vector>

#include "case/load.hpp"
#include "pd/setup.hpp"
#include "pd/stepper.hpp"

namespace coldspray::pd::testing {

inline State run_example(const std::string& name, const std::vector<case_file::Override>& overrides,
                         int steps) {
  const case_file::Case c =
      case_file::load_case(std::string(COLDSPRAY_SOURCE_DIR) + "/examples/" + name, overrides);
  State s = build_state(c);
  for (int k = 0; k < steps; ++k) {
    s.dt = stable_time_step(s, c.solver.cfl);
    step(s);
  }
  return s;
}

}  // namespace coldspray::pd::testing
