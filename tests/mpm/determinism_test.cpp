// The same case gives bit-identical results with 1 and 2 threads: point-to-grid sums run block by
// block in a fixed order (mpm/state.hpp), so the thread count cannot change any rounding; and
// points leaving the grid are chosen and removed in index order (mpm/departures.hpp).
#include <gtest/gtest.h>
#include <omp.h>

#include <string>
#include <utility>

#include "case/load.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"

namespace coldspray::mpm {
namespace {

State run_steps(const std::string& example, std::vector<case_file::Override> overrides, int threads,
                int steps) {
  omp_set_num_threads(threads);
  const case_file::Case c =
      case_file::load_case(std::string(COLDSPRAY_SOURCE_DIR) + "/examples/" + example, overrides);
  State s = build_state(c);
  for (int k = 0; k < steps; ++k) {
    s.dt = stable_time_step(s, c.solver.cfl);
    step(s);
  }
  return s;
}

// The case's state after `steps` steps on 1 thread and on 2; the thread count is restored.
std::pair<State, State> on_one_and_two_threads(const std::string& example,
                                               std::vector<case_file::Override> overrides,
                                               int steps) {
  const int threads = omp_get_max_threads();
  std::pair<State, State> states(run_steps(example, overrides, 1, steps),
                                 run_steps(example, overrides, 2, steps));
  omp_set_num_threads(threads);
  return states;
}

void expect_identical(const Points& a, const Points& b) {
  ASSERT_EQ(a.size(), b.size());
  for (int d = 0; d < 3; ++d)
    for (std::size_t p = 0; p < a.size(); ++p) {
      ASSERT_EQ(a.position[d][p], b.position[d][p]) << "point " << p;
      ASSERT_EQ(a.velocity[d][p], b.velocity[d][p]) << "point " << p;
    }
  for (int c = 0; c < 6; ++c)
    for (std::size_t p = 0; p < a.size(); ++p) ASSERT_EQ(a.stress[c][p], b.stress[c][p]);
}

// The r-z example, coarsened, for 60 steps on 1 and 2 threads, with `extra` overrides.
void expect_axisymmetric_impact_identical(std::vector<case_file::Override> extra) {
  std::vector<case_file::Override> coarse = {{"grid.cell_size", "1.4 um"},
                                             {"bodies.particle.spacing", "0.35 um"},
                                             {"bodies.substrate.spacing", "0.35 um"}};
  coarse.insert(coarse.end(), extra.begin(), extra.end());
  const auto [one, two] = on_one_and_two_threads("al-14um-810.yaml", coarse, 60);
  expect_identical(one.points, two.points);
  for (std::size_t p = 0; p < one.points.size(); ++p)
    ASSERT_EQ(one.points.temperature[p], two.points.temperature[p]);
}

TEST(MpmDeterminism, AxisymmetricImpactIsBitIdenticalOnOneAndTwoThreads) {
  expect_axisymmetric_impact_identical({});
}

TEST(MpmDeterminism, HeatConductionIsBitIdenticalOnOneAndTwoThreads) {
  expect_axisymmetric_impact_identical({{"solver.heat_conduction", "true"}});
}

TEST(MpmDeterminism, ThreeDimensionalTaylorBarIsBitIdenticalOnOneAndTwoThreads) {
  const auto [one, two] = on_one_and_two_threads("verification/taylor-bar-3d.yaml", {}, 40);
  expect_identical(one.points, two.points);
}

// Points leave the grid (mpm/departures.hpp): the same points leave, and the same remain.
TEST(MpmDeterminism, AFragmentLeavingTheGridIsBitIdenticalOnOneAndTwoThreads) {
  const auto [one, two] = on_one_and_two_threads("verification/fragment-leaves.yaml", {}, 36);
  ASSERT_EQ(one.bodies[0].departed.points, 4u);
  expect_identical(one.points, two.points);
  for (std::size_t b = 0; b < one.bodies.size(); ++b) {
    const Departed &d1 = one.bodies[b].departed, &d2 = two.bodies[b].departed;
    EXPECT_EQ(d1.points, d2.points);
    EXPECT_EQ(d1.mass, d2.mass);
    EXPECT_EQ(d1.momentum, d2.momentum);
    EXPECT_EQ(d1.kinetic, d2.kinetic);
    EXPECT_EQ(d1.internal, d2.internal);
    EXPECT_EQ(one.bodies[b].end, two.bodies[b].end);
  }
}

}  // namespace
}  // namespace coldspray::mpm
