// The step allocates nothing (issue 23's "the step must allocate nothing"; docs/solvers.md): the
// MPM's and the peridynamics' steps and the run's fault checks, counted with a replaced global
// operator new, over steps in which the peridynamics contact list is not rebuilt (a rebuild may
// grow it when more pairs come close than ever before, pd/state.hpp).
#include <gtest/gtest.h>

#include <atomic>
#include <cstddef>
#include <cstdlib>
#include <new>
#include <string>
#include <utility>
#include <vector>

#include "case/load.hpp"
#include "metrics/energy.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"
#include "pd/setup.hpp"
#include "pd/stepper.hpp"
#include "run/fault_checks.hpp"

namespace {

std::atomic<bool> counting{false};
std::atomic<long> allocations{0};

void* counted_malloc(std::size_t size, std::size_t align) {
  if (counting.load(std::memory_order_relaxed)) allocations.fetch_add(1);
  size = size == 0 ? 1 : size;
  return align <= alignof(std::max_align_t)
             ? std::malloc(size)
             : std::aligned_alloc(align, (size + align - 1) / align * align);
}
void* counted_new(std::size_t size, std::size_t align) {
  if (void* p = counted_malloc(size, align)) return p;
  throw std::bad_alloc();
}
constexpr std::size_t kPlain = alignof(std::max_align_t);

}  // namespace

// Replaces every form of the program's allocation functions (replaceable global functions,
// [new.delete]): all take from malloc and give back to free, so that no form left to the
// library (or to a sanitizer's runtime) frees what another allocated; counted only while
// `counting` is set.
void* operator new(std::size_t n) { return counted_new(n, kPlain); }
void* operator new[](std::size_t n) { return counted_new(n, kPlain); }
void* operator new(std::size_t n, std::align_val_t a) {
  return counted_new(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a) {
  return counted_new(n, static_cast<std::size_t>(a));
}
void* operator new(std::size_t n, const std::nothrow_t&) noexcept {
  return counted_malloc(n, kPlain);
}
void* operator new[](std::size_t n, const std::nothrow_t&) noexcept {
  return counted_malloc(n, kPlain);
}
void* operator new(std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return counted_malloc(n, static_cast<std::size_t>(a));
}
void* operator new[](std::size_t n, std::align_val_t a, const std::nothrow_t&) noexcept {
  return counted_malloc(n, static_cast<std::size_t>(a));
}
// GCC, inlining a delete next to the default-looking new it pairs with, would call the free a
// mismatch.
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wmismatched-new-delete"
void operator delete(void* p) noexcept { std::free(p); }
void operator delete[](void* p) noexcept { std::free(p); }
void operator delete(void* p, std::size_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete[](void* p, std::size_t, std::align_val_t) noexcept { std::free(p); }
void operator delete(void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete(void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
void operator delete[](void* p, std::align_val_t, const std::nothrow_t&) noexcept { std::free(p); }
#pragma GCC diagnostic pop

namespace coldspray {
namespace {

case_file::Case example(const std::string& name,
                        const std::vector<case_file::Override>& overrides = {}) {
  return case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/" + name + ".yaml", overrides);
}

// A step of either solver at its stable time step (found by argument-dependent lookup).
template <class State>
void advance(State& s, double cfl) {
  s.dt = stable_time_step(s, cfl);
  step(s);
}

// Allocations in the steps, after `warm` steps, over which `marker(state)` did not change;
// and the number of such steps.
template <class State, class Marker>
std::pair<long, int> allocations_in_steps(State& s, double cfl, int warm, int steps,
                                          Marker marker) {
  for (int n = 0; n < warm; ++n) advance(s, cfl);
  long counted = 0;
  int clean = 0;
  for (int n = 0; n < steps; ++n) {
    const long before = marker(s);
    allocations = 0;
    counting = true;
    advance(s, cfl);
    counting = false;
    if (marker(s) != before) continue;
    counted += allocations.load();
    ++clean;
  }
  return {counted, clean};
}

// The counter itself: it sees a vector's allocation.
TEST(StepAllocation, TheCounterSeesAnAllocation) {
  allocations = 0;
  counting = true;
  std::vector<double> v(1000, 1.0);
  counting = false;
  EXPECT_EQ(allocations.load(), 1);
  EXPECT_EQ(v[999], 1.0);
}

TEST(StepAllocation, TheMpmStepAllocatesNothing) {
  const case_file::Case c = example("bonding-impact");
  mpm::State s = mpm::build_state(c);
  const auto [counted, steps] =
      allocations_in_steps(s, c.solver.cfl, 20, 30, [](const mpm::State&) { return 0L; });
  EXPECT_EQ(steps, 30);
  EXPECT_EQ(counted, 0);
}

// The run's fault checks every kFaultCheckStride steps (run/fault_checks.hpp) are part of the
// step loop: on a valid state they allocate nothing either.
TEST(StepAllocation, TheFaultChecksAllocateNothing) {
  const case_file::Case c = example("bonding-impact");
  mpm::State s = mpm::build_state(c);
  const run::FaultChecks checks(metrics::energy_budget(s).total());
  for (int n = 0; n < 20; ++n) advance(s, c.solver.cfl);
  const metrics::EnergyBudget e = metrics::energy_budget(s);
  allocations = 0;
  counting = true;
  checks.check(s, e);
  counting = false;
  EXPECT_EQ(allocations.load(), 0);
}

// With the elastic control and with the control along the flow (its pairs' histories and slip
// fits are allocated at set-up); the quarter model, so that the step also mirrors its ghost points
// across the symmetry planes.
TEST(StepAllocation, ThePeridynamicsStepAllocatesNothingBetweenContactRebuilds) {
  for (const char* control : {"elastic", "flow"}) {
    const case_file::Case c =
        example("pd-quarter-impact", {{"symmetry.x", "0 um"},
                                      {"symmetry.y", "0 um"},
                                      {"peridynamics.control_stiffness", control}});
    pd::State s = pd::build_state(c);
    const auto [counted, steps] = allocations_in_steps(
        s, c.solver.cfl, 20, 40, [](const pd::State& st) { return st.contact.builds; });
    EXPECT_GT(steps, 20) << control;  // most steps reuse the contact list
    EXPECT_EQ(counted, 0) << control;
  }
}

}  // namespace
}  // namespace coldspray
