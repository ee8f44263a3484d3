#include "run/solver.hpp"

#include "mpm/setup.hpp"

namespace coldspray::run {

SolverState build_solver_state(const case_file::Case& c) { return mpm::build_state(c); }

}  // namespace coldspray::run
