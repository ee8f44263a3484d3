#include "run/solver.hpp"

#include "mpm/setup.hpp"
#include "pd/setup.hpp"

namespace coldspray::run {

SolverState build_solver_state(const case_file::Case& c) {
  switch (c.solver.method) {
    case case_file::Method::Peridynamics:
      return pd::build_state(c);
    case case_file::Method::Mpm:
      break;
  }
  return mpm::build_state(c);
}

}  // namespace coldspray::run
