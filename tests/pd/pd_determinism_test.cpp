// Peridynamics gives bit-identical results on 1 and 2 threads: every point sums over its own
// family and contacts in a fixed order and writes only its own results (pd/stepper.cpp), and
// the contact list is built serially.
#include <gtest/gtest.h>
#include <omp.h>

#include <string>

#include "case/load.hpp"
#include "pd/setup.hpp"
#include "pd/stepper.hpp"

namespace coldspray::pd {
namespace {

State run_steps(int threads, int steps) {
  omp_set_num_threads(threads);
  const case_file::Case c = case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/pd-elastic-spheres.yaml", {});
  State s = build_state(c);
  for (int k = 0; k < steps; ++k) {
    s.dt = stable_time_step(s, c.solver.cfl);
    step(s);
  }
  return s;
}

// 600 steps, 14.5 ns: the spheres, 1.5 um apart between their nearest points, close at
// 100 m/s and are in contact from about 10.5 ns.
TEST(PeridynamicDeterminism, ElasticSpheresAreBitIdenticalOnOneAndTwoThreads) {
  const int threads = omp_get_max_threads();
  const State one = run_steps(1, 600), two = run_steps(2, 600);
  omp_set_num_threads(threads);
  ASSERT_EQ(one.points.size(), two.points.size());
  EXPECT_GT(one.contact.builds, 1);
  bool touched = false;
  for (const auto& impulse : one.contact_impulse) touched = touched || impulse[2] != 0.0;
  EXPECT_TRUE(touched);
  for (std::size_t p = 0; p < one.points.size(); ++p) {
    for (int d = 0; d < 3; ++d) {
      ASSERT_EQ(one.points.position[d][p], two.points.position[d][p]) << "point " << p;
      ASSERT_EQ(one.points.velocity[d][p], two.points.velocity[d][p]) << "point " << p;
    }
    for (int c = 0; c < 6; ++c) ASSERT_EQ(one.points.stress[c][p], two.points.stress[c][p]);
  }
}

}  // namespace
}  // namespace coldspray::pd
