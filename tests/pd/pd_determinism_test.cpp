// Peridynamics gives bit-identical results on 1 and 2 threads: the pairs of neighbours are
// visited in blocks whose order of writes does not depend on the threads (pd/pair_forces.hpp),
// every other loop writes only its own point's results (pd/stepper.cpp), and the contact list is
// built serially.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <string>

#include "pd_example_run.hpp"

namespace coldspray::pd {
namespace {

// The elastic spheres, shrunk to 3 um radius (about 900 points each), started 0.5 um apart
// between their nearest points (in contact, 0.45 um, from 0.5 ns) and also sliding past each
// other at 2 x 250 m/s along x, so that the contact list is rebuilt every 0.5 ns or so (a point
// moves half the 0.25 um skin): cheap enough for the sanitizer build.
State run_steps(int threads, int steps) {
  omp_set_num_threads(threads);
  return testing::run_example(
      "verification/pd-elastic-spheres.yaml",
      {{"bodies.upper.shape", "{type: sphere, center: [0, 0, 3.05 um], radius: 3 um}"},
       {"bodies.lower.shape", "{type: sphere, center: [0, 0, -3.05 um], radius: 3 um}"},
       {"bodies.upper.velocity", "[250 m/s, 0, -50 m/s]"},
       {"bodies.lower.velocity", "[-250 m/s, 0, 50 m/s]"}},
      steps);
}

// 60 steps, 1.5 ns: into contact, and past rebuilds of the contact list.
TEST(PeridynamicDeterminism, ElasticSpheresAreBitIdenticalOnOneAndTwoThreads) {
  const int threads = omp_get_max_threads();
  const State one = run_steps(1, 60), two = run_steps(2, 60);
  omp_set_num_threads(threads);
  ASSERT_EQ(one.points.size(), two.points.size());
  EXPECT_GT(one.contact.builds, 1);
  EXPECT_GE(one.pairs.block.size(), 5u);  // four blocks or more: two at once in each colour
  EXPECT_GT(std::count(one.points.touched.begin(), one.points.touched.end(), 1), 0);
  for (std::size_t p = 0; p < one.points.size(); ++p) {
    for (int d = 0; d < 3; ++d) {
      ASSERT_EQ(one.points.position[d][p], two.points.position[d][p]) << "point " << p;
      ASSERT_EQ(one.points.velocity[d][p], two.points.velocity[d][p]) << "point " << p;
    }
    for (int c = 0; c < 6; ++c) ASSERT_EQ(one.points.stress[c][p], two.points.stress[c][p]);
  }
}

// Subcycling (pd/stepper.hpp): the lower sphere grown to 6.5 um radius at 1 um spacing, the
// largest body, so that the upper one, at 0.5 um, takes two steps per step of it; the slow
// sphere's contact impulses gather from the substeps, point by point.
TEST(PeridynamicDeterminism, SubcyclingIsBitIdenticalOnOneAndTwoThreads) {
  const int threads = omp_get_max_threads();
  auto run = [](int n) {
    omp_set_num_threads(n);
    return testing::run_example(
        "verification/pd-elastic-spheres.yaml",
        {{"bodies.upper.shape", "{type: sphere, center: [0, 0, 3.05 um], radius: 3 um}"},
         {"bodies.lower.shape", "{type: sphere, center: [0, 0, -6.55 um], radius: 6.5 um}"},
         {"bodies.lower.spacing", "1 um"},
         {"bodies.upper.velocity", "[250 m/s, 0, -50 m/s]"},
         {"bodies.lower.velocity", "[-250 m/s, 0, 50 m/s]"},
         {"peridynamics.subcycling", "true"}},
        40);
  };
  const State one = run(1), two = run(2);
  omp_set_num_threads(threads);
  EXPECT_EQ(one.substeps, 2);
  EXPECT_GT(std::count(one.points.touched.begin(), one.points.touched.end(), 1), 0);
  for (std::size_t p = 0; p < one.points.size(); ++p)
    for (int d = 0; d < 3; ++d) {
      ASSERT_EQ(one.points.position[d][p], two.points.position[d][p]) << "point " << p;
      ASSERT_EQ(one.points.velocity[d][p], two.points.velocity[d][p]) << "point " << p;
    }
}

// The coarse quarter Cu impact with the control along the flow (pd/control_along_flow.hpp),
// whose pairs keep their penalty displacements and whose slip fits gather from both ends of each
// pair, over 60 steps of plastic flow.
TEST(PeridynamicDeterminism, ControlAlongTheFlowIsBitIdenticalOnOneAndTwoThreads) {
  const int threads = omp_get_max_threads();
  auto run = [](int n) {
    omp_set_num_threads(n);
    return testing::run_example("verification/pd-quarter-impact.yaml",
                                {{"symmetry.x", "0 um"},
                                 {"symmetry.y", "0 um"},
                                 {"peridynamics.control_stiffness", "flow"}},
                                60);
  };
  const State one = run(1), two = run(2);
  omp_set_num_threads(threads);
  EXPECT_GE(one.pairs.block.size(), 5u);
  EXPECT_GT(std::count(one.slipped.begin(), one.slipped.end(), 1), 0);
  ASSERT_EQ(one.control_displacement.size(), two.control_displacement.size());
  for (std::size_t k = 0; k < one.control_displacement.size(); ++k)
    ASSERT_EQ(one.control_displacement[k], two.control_displacement[k]) << "pair " << k;
  for (std::size_t p = 0; p < one.points.size(); ++p)
    for (int d = 0; d < 3; ++d) {
      ASSERT_EQ(one.points.position[d][p], two.points.position[d][p]) << "point " << p;
      ASSERT_EQ(one.points.velocity[d][p], two.points.velocity[d][p]) << "point " << p;
    }
}

}  // namespace
}  // namespace coldspray::pd
