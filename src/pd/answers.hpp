// What peridynamics answers where a layer above its step loop asks a question each solver
// answers in its own way (docs/solvers.md, "The seam"), reached as mpm/answers.hpp's are, through
// the Solver tag run::with_solver (run/solver.hpp) hands its caller.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>

#include "case/case.hpp"
#include "metrics/interface_areas.hpp"
#include "pd/setup.hpp"
#include "pd/state.hpp"

namespace coldspray::pd {

// Peridynamics as run::with_solver names it.
using Solver = std::type_identity<State>;

inline State build_state(Solver, const case_file::Case& c) { return build_state(c); }

// The case summary's line for the discretisation (lengths in `unit` m, written `symbol`).
std::string describe_discretisation(Solver, const case_file::Case& c, double unit,
                                    std::string_view symbol);

// --- The pull-off test (studies/pull_off.hpp, docs/pull-off.md) ---

// Whether anything holds a body to the others: an adhesive contact law.
bool holds_bonds(Solver, const case_file::Case& c);
// Why not, when holds_bonds is false, after the impact folder's name.
std::string_view unbonded_reason(Solver);
// The contact law is the impact's: nothing changes for the pull.
inline void debond_during_pull(Solver, case_file::Case&) {}
// The substrate's bottom is held in the impact already.
inline void hold_for_pull(Solver, case_file::Case&, std::size_t) {}
// The grip's travel when the user gives none, m.
double default_pull_distance(Solver, const case_file::Case& c, std::size_t body,
                             const metrics::InterfaceAreas& areas);
// The bonded area of body `body`: of its points another body acts on.
void measure_bonds(const case_file::Case& c, const State& s, std::size_t body,
                   metrics::InterfaceAreas& areas);

}  // namespace coldspray::pd
