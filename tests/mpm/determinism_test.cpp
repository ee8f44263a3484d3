// The same case gives bit-identical results with 1 and 2 threads: point-to-grid sums run block by
// block in a fixed order (mpm/state.hpp), so the thread count cannot change any rounding.
#include <gtest/gtest.h>
#include <omp.h>

#include <string>

#include "case/load.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"

namespace coldspray::mpm {
namespace {

Points run_steps(const std::string& example, std::vector<case_file::Override> overrides,
                 int threads, int steps) {
  omp_set_num_threads(threads);
  const case_file::Case c =
      case_file::load_case(std::string(COLDSPRAY_SOURCE_DIR) + "/examples/" + example, overrides);
  State s = build_state(c);
  for (int k = 0; k < steps; ++k) {
    s.dt = stable_time_step(s, c.solver.cfl);
    step(s);
  }
  return s.points;
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
  const int threads = omp_get_max_threads();
  const Points one = run_steps("al-14um-810.yaml", coarse, 1, 60);
  const Points two = run_steps("al-14um-810.yaml", coarse, 2, 60);
  omp_set_num_threads(threads);
  expect_identical(one, two);
  for (std::size_t p = 0; p < one.size(); ++p) ASSERT_EQ(one.temperature[p], two.temperature[p]);
}

TEST(MpmDeterminism, AxisymmetricImpactIsBitIdenticalOnOneAndTwoThreads) {
  expect_axisymmetric_impact_identical({});
}

TEST(MpmDeterminism, HeatConductionIsBitIdenticalOnOneAndTwoThreads) {
  expect_axisymmetric_impact_identical({{"solver.heat_conduction", "true"}});
}

TEST(MpmDeterminism, ThreeDimensionalTaylorBarIsBitIdenticalOnOneAndTwoThreads) {
  const int threads = omp_get_max_threads();
  const Points one = run_steps("verification/taylor-bar-3d.yaml", {}, 1, 40);
  const Points two = run_steps("verification/taylor-bar-3d.yaml", {}, 2, 40);
  omp_set_num_threads(threads);
  expect_identical(one, two);
}

}  // namespace
}  // namespace coldspray::mpm
