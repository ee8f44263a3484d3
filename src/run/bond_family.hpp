// Runs that differ only in their bonding parameters, run together, as a calibration's grid over
// (G_c, Gdot_c) is. D_bond acts on the mechanics only where a contact node bonds (bond_forms,
// thesis eq 4.7), so until then every member moves exactly as an unbonded run does. The family
// steps that one shared run (the trunk), following every member's D_bond beside it
// (mpm/bond_shadows.hpp); at the step where a member's nodal D_bond first reaches 1 the trunk is
// copied, the copy given that member's D_bond and law, and the member goes on alone (a branch).
// Members that never bond are finished from the trunk. Each member's folder gets what run_case
// would write for it, bit for bit, except the wall time: its summary counts the shared steps in
// full in wall_seconds and reports them as shared_steps.
#pragma once

#include <cstddef>
#include <exception>
#include <filesystem>
#include <functional>
#include <vector>

#include "case/case.hpp"

namespace coldspray::run {

struct FamilyMember {
  case_file::Case c;
  std::filesystem::path out_dir;
};

struct FamilyHooks {
  // Takes a branch's remaining run, to be called once, on any thread, with this thread's
  // OpenMP setting (the caller's scheduler; calling it at once is fine).
  std::function<void(std::function<void()>)> spawn;
  // Called once per member, on the thread that finished it (so possibly from several threads at
  // once), and must not throw: null when its run went to the end, else why it did not (an
  // InputError, a RunFault after the fault's summary was written, or any other exception, with
  // no summary written for it).
  std::function<void(std::size_t member, std::exception_ptr failure)> finished;
};

// Whether run_bond_family can run the cases together: the same bonding model (not none), and
// otherwise equal but for the bonding parameters, name and description.
bool same_but_bonding(const case_file::Case& a, const case_file::Case& b);

// Runs the members as one family; throws std::invalid_argument if two are not same_but_bonding,
// and otherwise reports every outcome through hooks.finished, never by throwing.
void run_bond_family(const std::vector<FamilyMember>& members, const FamilyHooks& hooks);

}  // namespace coldspray::run
