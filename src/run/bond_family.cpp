#include "run/bond_family.hpp"

#include <fmt/format.h>

#include <chrono>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "case/load.hpp"
#include "core/error.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"
#include "run/recorder.hpp"
#include "run/run.hpp"
#include "run/step_rule.hpp"

namespace coldspray::run {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// A member gone its own way: the trunk halfway through the step where the member's first node
// bonded, with the member's D_bond and law; and the member's recorder.
struct Branch {
  mpm::State state;
  std::unique_ptr<Recorder> recorder;
  std::size_t member = 0;
};

std::string resolved(const case_file::Case& c) {
  std::ostringstream out;
  case_file::write_resolved(c, out);
  return out.str();
}

}  // namespace

bool same_but_bonding(const case_file::Case& a, const case_file::Case& b) {
  if (a.bonding.model == case_file::BondingModel::None || a.bonding.model != b.bonding.model)
    return false;
  case_file::Case like_a = b;
  like_a.name = a.name;
  like_a.description = a.description;
  like_a.source_file = a.source_file;
  like_a.bonding = a.bonding;
  return resolved(like_a) == resolved(a);
}

void run_bond_family(const std::vector<FamilyMember>& members, const FamilyHooks& hooks) {
  if (members.empty()) return;
  for (std::size_t i = 1; i < members.size(); ++i)
    if (!same_but_bonding(members[0].c, members[i].c))
      throw std::invalid_argument(
          fmt::format("bond family: '{}' differs from '{}' in more than its bonding parameters",
                      members[i].out_dir.string(), members[0].out_dir.string()));

  mpm::State trunk;
  try {
    trunk = mpm::build_state(members[0].c);
  } catch (...) {
    for (std::size_t i = 0; i < members.size(); ++i) hooks.finished(i, std::current_exception());
    return;
  }
  std::vector<bonding::BondLaw> laws;
  for (const FamilyMember& m : members)
    laws.push_back(bonding::BondLaw::from_case(m.c.bonding, m.c.grid.cell_size));
  mpm::BondShadows& shadows = trunk.bond_shadows;
  shadows.follow(laws, trunk.points);
  const StepRule rule(members[0].c, trunk);

  // Each member's folder and its t = 0 outputs; a member whose folder cannot be written is out.
  std::vector<std::unique_ptr<Recorder>> recorders(members.size());
  for (std::size_t k = shadows.size(); k-- > 0;) {
    const std::size_t i = shadows.id(k);
    try {
      const auto t0 = Clock::now();
      recorders[i] = std::make_unique<Recorder>(members[i].c, trunk, members[i].out_dir);
      recorders[i]->start(trunk);
      recorders[i]->add_wall(seconds_since(t0));
    } catch (...) {
      shadows.drop(k);
      hooks.finished(i, std::current_exception());
    }
  }

  // Shadow k's member leaves, halfway through the step (`shared` seconds into it). Returns the
  // time spent handing it on (the scheduler may run it there and then), not the trunk's.
  auto branch_off = [&](std::size_t k, double shared) {
    auto branch = std::make_shared<Branch>();
    mpm::BondShadows followed = std::exchange(trunk.bond_shadows, {});
    branch->state = trunk;  // without the shadows
    trunk.bond_shadows = std::move(followed);
    shadows.impose(k, branch->state.points, branch->state.contact);
    branch->state.bond_law = shadows.law(k);
    branch->member = shadows.id(k);
    branch->recorder = std::move(recorders[branch->member]);
    branch->recorder->add_wall(shared);
    const auto handing = Clock::now();
    hooks.spawn([branch, rule, finished = hooks.finished] {
      std::exception_ptr failure;
      try {
        run_to_end(branch->state, rule, *branch->recorder, /*progress=*/false, ResumeAt::Contact);
      } catch (...) {
        failure = std::current_exception();
      }
      finished(branch->member, failure);
    });
    return seconds_since(handing);
  };

  // The members still on the trunk, finished from it: at its end, or with the trunk's fault.
  auto finish_followed = [&](const RunFault* fault) {
    const std::string status = fault ? fmt::format("fault: {}", fault->what()) : "ok";
    for (std::size_t k = 0; k < shadows.size(); ++k) {
      const std::size_t i = shadows.id(k);
      std::exception_ptr failure;
      try {
        shadows.write_bond(k, trunk.points);
        recorders[i]->finish(trunk, status);
        if (fault)
          throw RunFault(fmt::format("{} (last snapshot and summary in {})", fault->what(),
                                     members[i].out_dir.string()));
      } catch (...) {
        failure = std::current_exception();
      }
      hooks.finished(i, failure);
    }
    shadows.clear_bond(trunk.points);
  };

  try {
    while (shadows.active() && !rule.finished(trunk)) {
      const auto t0 = Clock::now();
      trunk.dt = rule.next_dt(trunk);
      mpm::step_to_contact(trunk);
      const double shared = seconds_since(t0);
      double handed_on = 0.0;
      for (std::size_t k = shadows.size(); k-- > 0;)
        if (shadows.bonds_now(k, trunk.contact)) {
          handed_on += branch_off(k, shared);
          shadows.drop(k);
        }
      if (!shadows.active()) return;
      mpm::step_from_contact(trunk);
      const bool last = rule.finished(trunk);
      for (std::size_t k = 0; k < shadows.size(); ++k) {
        Recorder& rec = *recorders[shadows.id(k)];
        if (!rec.due(trunk, last)) continue;
        shadows.write_bond(k, trunk.points);
        rec.after_step(trunk, last);
      }
      shadows.clear_bond(trunk.points);
      const double wall = seconds_since(t0) - handed_on;
      for (std::size_t k = 0; k < shadows.size(); ++k) {
        recorders[shadows.id(k)]->add_wall(wall);
        recorders[shadows.id(k)]->add_shared_step();
      }
    }
  } catch (const RunFault& fault) {
    finish_followed(&fault);
    return;
  } catch (...) {
    for (std::size_t k = 0; k < shadows.size(); ++k)
      hooks.finished(shadows.id(k), std::current_exception());
    return;
  }
  finish_followed(nullptr);
}

}  // namespace coldspray::run
