#include "run/solver.hpp"

namespace coldspray::run {

SolverState build_solver_state(const case_file::Case& c) {
  return with_solver(c.solver.method,
                     [&](auto solver) -> SolverState { return build_state(solver, c); });
}

}  // namespace coldspray::run
