#include "run/bond_family.hpp"

#include <fmt/format.h>

#include <chrono>
#include <functional>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <utility>

#include "case/load.hpp"
#include "core/error.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"
#include "run/interrupt.hpp"
#include "run/recorder.hpp"
#include "run/run.hpp"
#include "run/step_rule.hpp"

namespace coldspray::run {

namespace {

using Clock = std::chrono::steady_clock;

double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

std::string resolved(const case_file::Case& c) {
  std::ostringstream out;
  case_file::write_resolved(c, out);
  return out.str();
}

// A member gone its own way: the trunk halfway through the step where the member's first node
// bonded, with the member's D_bond and law; and the member's recorder.
struct Branch {
  mpm::State state;
  std::unique_ptr<Recorder> recorder;
  std::size_t member = 0;
};

// The shared run and the members still on it (its bond shadows). Every member leaves it once,
// through branch_off, end_member or fail_member, each of which calls hooks.finished or hands the
// member on to a branch that does.
class Trunk {
 public:
  Trunk(const std::vector<FamilyMember>& members, const FamilyHooks& hooks, mpm::State state)
      : members_(members),
        hooks_(hooks),
        state_(std::move(state)),
        shadows_(state_.bond_shadows),
        rule_(members[0].c, state_),
        recorders_(members.size()) {}

  void run() {
    open_recorders();
    while (shadows_.active() && !rule_.finished(state_)) {
      const auto t0 = Clock::now();
      state_.dt = rule_.next_dt(state_);
      if (!step(mpm::step_to_contact)) return;
      const double shared = seconds_since(t0);
      double handed_on = 0.0;
      for (std::size_t k = shadows_.size(); k-- > 0;)
        if (shadows_.bonds_now(k, state_.contact, state_.contact_rule.nodal_average, state_.bodies))
          handed_on += branch_off(k, shared);
      if (!shadows_.active()) return;
      if (!step(mpm::step_from_contact)) return;
      sample_members();
      if (rule_.finished(state_)) extend_undecided(seconds_since(t0) - handed_on);
      record_step(rule_.finished(state_));
      const double wall = seconds_since(t0) - handed_on;
      for (std::size_t k = 0; k < shadows_.size(); ++k) {
        recorders_[shadows_.id(k)]->add_wall(wall);
        recorders_[shadows_.id(k)]->add_shared_step();
      }
      if (const int signal = pending_interrupt()) {
        for (std::size_t k = shadows_.size(); k-- > 0;) interrupt_member(k, signal);
        return;
      }
    }
    for (std::size_t k = shadows_.size(); k-- > 0;) end_member(k, nullptr);
  }

 private:
  // Each member's folder and its t = 0 outputs.
  void open_recorders() {
    for (std::size_t k = shadows_.size(); k-- > 0;) {
      const std::size_t i = shadows_.id(k);
      try {
        const auto t0 = Clock::now();
        recorders_[i] = std::make_unique<Recorder>(members_[i].c, state_, members_[i].out_dir);
        recorders_[i]->start(state_);
        recorders_[i]->add_wall(seconds_since(t0));
      } catch (...) {
        fail_member(k, std::current_exception());
      }
    }
  }

  // Half a step of the trunk; a fault in it ends every member still on it, as it would each
  // alone. Returns whether the trunk goes on.
  bool step(void (*half)(mpm::State&)) {
    try {
      half(state_);
      return true;
    } catch (const RunFault& fault) {
      for (std::size_t k = shadows_.size(); k-- > 0;) end_member(k, &fault);
    } catch (...) {
      for (std::size_t k = shadows_.size(); k-- > 0;) fail_member(k, std::current_exception());
    }
    return false;
  }

  // The verdict samples due, each member's with its own D_bond (its bonded area).
  void sample_members() {
    for (std::size_t k = shadows_.size(); k-- > 0;) {
      Recorder& rec = *recorders_[shadows_.id(k)];
      if (!rec.sample_due(state_, rule_)) continue;
      shadows_.write_bond(k, state_.points);
      rec.sample(state_);
    }
    shadows_.clear_bond(state_.points);
  }

  // At the end time, as each member would alone (run_to_end): if a member's verdict is undecided
  // and the rule has an extension left, the undecided members go on one more window and the
  // others end here, with this step (`wall` seconds of it so far) counted as shared; otherwise
  // all end with the loop.
  void extend_undecided(double wall) {
    bool any = false;
    for (std::size_t k = 0; k < shadows_.size(); ++k)
      any = any || recorders_[shadows_.id(k)]->undecided();
    if (!any || !rule_.extend()) return;
    for (std::size_t k = shadows_.size(); k-- > 0;) {
      Recorder& rec = *recorders_[shadows_.id(k)];
      if (rec.undecided()) {
        rec.add_extension();
        continue;
      }
      rec.add_wall(wall);
      rec.add_shared_step();
      if (record(k, /*last=*/true)) end_member(k, nullptr);
    }
    shadows_.clear_bond(state_.points);
  }

  // The rows and snapshots due, each member's with its own D_bond.
  void record_step(bool last) {
    for (std::size_t k = shadows_.size(); k-- > 0;) record(k, last);
    shadows_.clear_bond(state_.points);
  }

  // Member k's rows and snapshot due. A member whose recording fails ends as it would alone
  // (run_to_end): a RunFault with its last snapshot and summary. Returns whether it is still on
  // the trunk.
  bool record(std::size_t k, bool last) {
    Recorder& rec = *recorders_[shadows_.id(k)];
    if (!rec.due(state_, last)) return true;
    try {
      shadows_.write_bond(k, state_.points);
      rec.after_step(state_, last);
      return true;
    } catch (const RunFault& fault) {
      end_member(k, &fault);
    } catch (...) {
      fail_member(k, std::current_exception());
    }
    return false;
  }

  // Shadow k's member leaves, halfway through the step (`shared` seconds into it): a copy of the
  // trunk with its D_bond, sums and law goes to the scheduler. Returns the time spent handing it
  // on (the scheduler may run it there and then), which is not the trunk's.
  double branch_off(std::size_t k, double shared) {
    const auto handing = Clock::now();
    const std::size_t i = shadows_.id(k);
    try {
      auto branch = std::make_shared<Branch>();
      branch->state = state_;
      branch->state.bond_shadows = {};
      shadows_.impose(k, branch->state.points, branch->state.contact);
      branch->state.bond_law = shadows_.law(k);
      branch->state.contact_rule.activation = shadows_.law(k).critical_penetration > 0.0;
      mpm::activate_bonding(branch->state);  // this step's, by its own law
      branch->member = i;
      branch->recorder = std::move(recorders_[i]);
      branch->recorder->add_wall(shared);
      shadows_.drop(k);
      hooks_.spawn([branch, rule = rule_, finished = hooks_.finished] {
        std::exception_ptr failure;
        try {
          run_to_end(branch->state, rule, *branch->recorder, /*progress=*/false, ResumeAt::Contact);
        } catch (...) {
          failure = std::current_exception();
        }
        finished(branch->member, failure);
      });
    } catch (...) {  // no memory for the copy, or the scheduler refused it
      if (shadows_.size() > k && shadows_.id(k) == i)
        fail_member(k, std::current_exception());
      else
        hooks_.finished(i, std::current_exception());
    }
    return seconds_since(handing);
  }

  // Shadow k's member ends on the trunk: at the end (`fault` null) or with the fault, as
  // run_to_end ends a run: the last snapshot and the summary, then the RunFault.
  void end_member(std::size_t k, const RunFault* fault) {
    finish_member(k, [&](Recorder& rec) {
      if (fault) rec.end_with_fault(state_, *fault);
      rec.finish(state_, "ok");
    });
  }

  // Shadow k's member stops on SIGINT or SIGTERM, as run_to_end stops a run (but without a
  // checkpoint: a family's members write none): its last rows, snapshot and summary, then
  // Interrupted.
  void interrupt_member(std::size_t k, int signal) {
    finish_member(k, [&](Recorder& rec) { rec.end_interrupted(state_, signal); });
  }

  // Shadow k's member ends with its own D_bond by `end` (of its recorder) and leaves with what
  // that throws, if anything.
  void finish_member(std::size_t k, const std::function<void(Recorder&)>& end) {
    const std::size_t i = shadows_.id(k);
    std::exception_ptr failure;
    try {
      shadows_.write_bond(k, state_.points);
      end(*recorders_[i]);
    } catch (...) {
      failure = std::current_exception();
    }
    shadows_.clear_bond(state_.points);
    fail_member(k, failure);
  }

  // Shadow k's member leaves with `failure` (null: none).
  void fail_member(std::size_t k, std::exception_ptr failure) {
    const std::size_t i = shadows_.id(k);
    recorders_[i].reset();
    shadows_.drop(k);
    hooks_.finished(i, std::move(failure));
  }

  const std::vector<FamilyMember>& members_;
  const FamilyHooks& hooks_;
  mpm::State state_;
  mpm::BondShadows& shadows_;
  StepRule rule_;
  std::vector<std::unique_ptr<Recorder>> recorders_;
};

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

  mpm::State state;
  try {
    state = mpm::build_state(members[0].c);
  } catch (...) {
    for (std::size_t i = 0; i < members.size(); ++i) hooks.finished(i, std::current_exception());
    return;
  }
  std::vector<bonding::BondLaw> laws;
  for (const FamilyMember& m : members)
    laws.push_back(bonding::BondLaw::from_case(m.c.bonding, m.c.grid->cell_size));
  state.bond_shadows.follow(laws, state.points);
  Trunk(members, hooks, std::move(state)).run();
}

}  // namespace coldspray::run
