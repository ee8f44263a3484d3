// The solvers a case can run on, as one variant dispatched once per run (std::visit), as the
// material models are dispatched once per body. Each alternative is a solver's whole state, a
// bodies::Bodies (what the recorder, the metrics and the studies read), with beside it in its
// namespace stable_time_step(const State&, double cfl) and the step (docs/solvers.md). Before a
// state exists, with_solver is the one dispatch on solver.method: what differs by solver is
// answered in the solver's answers.hpp.
#pragma once

#include <variant>

#include "bodies/bodies.hpp"
#include "case/case.hpp"
#include "mpm/answers.hpp"
#include "mpm/state.hpp"
#include "pd/answers.hpp"
#include "pd/state.hpp"

namespace coldspray::run {

using SolverState = std::variant<mpm::State, pd::State>;

// Calls f with the Solver tag of `method` (mpm::Solver or pd::Solver), through which f reaches
// that solver's answers (mpm/answers.hpp, pd/answers.hpp) by argument-dependent lookup; f
// returns the same type for both.
template <class F>
decltype(auto) with_solver(case_file::Method method, F&& f) {
  switch (method) {
    case case_file::Method::Peridynamics:
      return f(pd::Solver{});
    case case_file::Method::Mpm:
      break;
  }
  return f(mpm::Solver{});
}

// The solver's state at t = 0 for the case; throws InputError before anything is written if the
// case's geometry is invalid.
SolverState build_solver_state(const case_file::Case& c);

// The bodies of whichever solver's state.
inline const bodies::Bodies& bodies_of(const SolverState& state) {
  return std::visit([](const auto& s) -> const bodies::Bodies& { return s; }, state);
}

}  // namespace coldspray::run
