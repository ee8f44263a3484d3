// What the MPM answers where a layer above its step loop asks a question each solver answers in
// its own way (docs/solvers.md, "The seam"). run::with_solver (run/solver.hpp), the one dispatch
// on solver.method, hands its caller a Solver tag, through which a call such as
// holds_bonds(solver, c) finds these functions by argument-dependent lookup; pd/answers.hpp
// answers the same for peridynamics.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>
#include <type_traits>

#include "case/case.hpp"
#include "metrics/interface_areas.hpp"
#include "mpm/setup.hpp"
#include "mpm/state.hpp"

namespace coldspray::mpm {

// The MPM as run::with_solver names it.
using Solver = std::type_identity<State>;

inline State build_state(Solver, const case_file::Case& c) { return build_state(c); }

// The case summary's line for the discretisation, lengths in `unit` (m) written `symbol`.
std::string describe_discretisation(Solver, const case_file::Case& c, double unit,
                                    std::string_view symbol);

// --- The pull-off test (studies/pull_off.hpp, docs/pull-off.md) ---

// Whether anything holds a body to the others: the bonding model.
bool holds_bonds(Solver, const case_file::Case& c);
// Why not, when holds_bonds is false, after the impact folder's name.
std::string_view unbonded_reason(Solver);
// The bonds let go under the debonding law during the pull even where the impact ran without it.
void debond_during_pull(Solver, case_file::Case& c);
// The other bodies held at their bottoms during the pull of body `pulled`.
void hold_for_pull(Solver, case_file::Case& c, std::size_t pulled);
// The grip's travel when the user gives none, m.
double default_pull_distance(Solver, const case_file::Case& c, std::size_t body,
                             const metrics::InterfaceAreas& areas);
// The bonded area of body `body`, and with the debonding law its bonded points.
void measure_bonds(const case_file::Case& c, const State& s, std::size_t body,
                   metrics::InterfaceAreas& areas);

}  // namespace coldspray::mpm
