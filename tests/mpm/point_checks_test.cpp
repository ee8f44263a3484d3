// The MPM step's checks of each point after its update (mpm/update_stress.cpp, check_point): a
// non-finite value in any of the stress's components stops the step with a RunFault naming the
// cause, rather than running on with NaN. (check_point tests all six components; a NaN in a
// shear component also reaches the normal ones through the rotation of the stress, so this test
// holds with either.)
#include <gtest/gtest.h>

#include <limits>
#include <string>

#include "case/load.hpp"
#include "core/error.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"

namespace coldspray::mpm {
namespace {

void expect_fault_from_stress_component(int component) {
  const case_file::Case c =
      case_file::load_case(std::string(COLDSPRAY_SOURCE_DIR) + "/examples/al-14um-810.yaml",
                           {{"grid.cell_size", "1.4 um"},
                            {"bodies.particle.spacing", "0.35 um"},
                            {"bodies.substrate.spacing", "0.35 um"}});
  State s = build_state(c);
  s.dt = stable_time_step(s, c.solver.cfl);
  step(s);  // a clean step first
  s.points.stress[component][10] = std::numeric_limits<double>::quiet_NaN();
  s.dt = stable_time_step(s, c.solver.cfl);
  try {
    step(s);
    FAIL() << "no fault for a NaN in stress component " << component;
  } catch (const RunFault& e) {
    EXPECT_NE(std::string(e.what()).find("non-finite position, velocity or stress"),
              std::string::npos)
        << e.what();
  }
}

TEST(PointChecks, ANonFiniteNormalStressIsAFault) {
  expect_fault_from_stress_component(bodies::kZZ);
}

TEST(PointChecks, ANonFiniteShearStressIsAFault) {
  for (int c : {bodies::kXY, bodies::kYZ, bodies::kXZ}) expect_fault_from_stress_component(c);
}

}  // namespace
}  // namespace coldspray::mpm
