// A small peridynamics model steps on one thread whatever the thread count (pd::threaded,
// pd/state.hpp): each of a step's parallel loops would hold a few microseconds of work per
// thread, and on a loaded machine every fork and join of a team waited for a descheduled thread
// (issue 53: the 252-point pull-off took 34 s on 2 threads beside two busy loops, 0.29 s on 1).
// The count below is of the teams the step asks libgomp for: GCC passes a parallel region whose
// `if` is false to GOMP_parallel with one thread, any other with 0 (the default) or its count.
#include <dlfcn.h>
#include <gtest/gtest.h>
#include <omp.h>

#include <atomic>
#include <string>

#include "case/load.hpp"
#include "pd/setup.hpp"
#include "pd/stepper.hpp"

namespace {

std::atomic<long> g_teams{0};  // regions entered asking for more than one thread

}  // namespace

// Stands in for libgomp's entry of `#pragma omp parallel` in this test program (the library is
// linked in statically, so its calls bind here) and passes every call on to libgomp's.
extern "C" void GOMP_parallel(void (*fn)(void*), void* data, unsigned threads, unsigned flags) {
  using Entry = void (*)(void (*)(void*), void*, unsigned, unsigned);
  static const auto real = reinterpret_cast<Entry>(dlsym(RTLD_NEXT, "GOMP_parallel"));
  if (threads != 1) g_teams.fetch_add(1, std::memory_order_relaxed);
  real(fn, data, threads, flags);
}

namespace coldspray::pd {
namespace {

struct Stepped {
  State state;
  long teams = 0;  // asked for in the steps
};

Stepped run_steps(const std::string& file, const std::vector<case_file::Override>& overrides,
                  int threads, int steps) {
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
  const case_file::Case c = case_file::load_case(file, overrides);
  Stepped r{build_state(c)};
  const long start = g_teams.load();
  for (int k = 0; k < steps; ++k) {
    r.state.dt = stable_time_step(r.state, c.solver.cfl);
    step(r.state);
  }
  r.teams = g_teams.load() - start;
  omp_set_num_threads(before);
  return r;
}

const std::string kBlocks = std::string(COLDSPRAY_TEST_DATA) + "/cli/pd-bonded-blocks.yaml";
const std::string kSpheres =
    std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/pd-elastic-spheres.yaml";

// The spheres shrunk to 3 um radius, 1840 points: above the bound, so their steps fork teams
// (and this program's count sees libgomp's calls at all).
TEST(PeridynamicThreads, AModelAboveTheBoundForksTeams) {
  const Stepped s =
      run_steps(kSpheres,
                {{"bodies.upper.shape", "{type: sphere, center: [0, 0, 3.05 um], radius: 3 um}"},
                 {"bodies.lower.shape", "{type: sphere, center: [0, 0, -3.05 um], radius: 3 um}"}},
                2, 5);
  ASSERT_GE(s.state.points.size(), kMinThreadedPoints);
  if (s.teams == 0) GTEST_SKIP() << "the OpenMP runtime is not libgomp: nothing to count";
  EXPECT_TRUE(threaded(s.state));
  EXPECT_GE(s.teams, 5 * 10);  // 17 a step with the default settings
}

// The pull-off test's two blocks (252 points, tests/data/cli/pd-bonded-blocks.yaml): on 2
// threads their steps fork no team, and their results are those of 1 thread, bit for bit.
TEST(PeridynamicThreads, ASmallModelForksNoTeamAndKeepsItsBits) {
  const Stepped two = run_steps(kBlocks, {}, 2, 40);
  const Stepped one = run_steps(kBlocks, {}, 1, 40);
  ASSERT_LT(two.state.points.size(), kMinThreadedPoints);
  EXPECT_FALSE(threaded(two.state));
  EXPECT_EQ(two.teams, 0);
  ASSERT_EQ(one.state.points.size(), two.state.points.size());
  for (std::size_t p = 0; p < one.state.points.size(); ++p)
    for (int d = 0; d < 3; ++d) {
      ASSERT_EQ(one.state.points.position[d][p], two.state.points.position[d][p]) << p;
      ASSERT_EQ(one.state.points.velocity[d][p], two.state.points.velocity[d][p]) << p;
    }
}

}  // namespace
}  // namespace coldspray::pd
