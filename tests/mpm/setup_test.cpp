// Building the state of a case: a body cut at symmetry planes remembers them, so its initial
// diameter (the flattening ratio's reference) is the whole body's.
#include "mpm/setup.hpp"

#include <gtest/gtest.h>

#include <string>

#include "case/load.hpp"

namespace coldspray::mpm {
namespace {

State build(const std::string& example) {
  const std::vector<case_file::Override> coarse = {{"grid.cell_size", "2 um"},
                                                   {"bodies.particle.spacing", "1 um"},
                                                   {"bodies.substrate.spacing", "1 um"}};
  return build_state(case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/coldspray/" + example, coarse));
}

TEST(MpmSetup, AQuarterModelKnowsItsSymmetryPlanes) {
  const State s = build("al-14um-810-3d.yaml");
  const BodyRange& particle = s.bodies[0];
  ASSERT_EQ(particle.name, "particle");
  ASSERT_TRUE(particle.mirror_plane[0] && particle.mirror_plane[1]);
  EXPECT_DOUBLE_EQ(*particle.mirror_plane[0], 0.0);
  EXPECT_DOUBLE_EQ(*particle.mirror_plane[1], 0.0);
  // The 14 um sphere on a 1 um lattice (points at +-0.5, ..., +-6.5 um): 13 um + one spacing.
  EXPECT_NEAR(particle.initial_diameter, 14e-6, 1e-12);
}

TEST(MpmSetup, AnAxisymmetricBodyIsMirroredAtTheAxis) {
  const State s = build("al-14um-810-rz.yaml");
  const BodyRange& particle = s.bodies[0];
  ASSERT_TRUE(particle.mirror_plane[0]);
  EXPECT_DOUBLE_EQ(*particle.mirror_plane[0], 0.0);
  EXPECT_FALSE(particle.mirror_plane[1]);
  EXPECT_NEAR(particle.initial_diameter, 14e-6, 1e-12);
}

}  // namespace
}  // namespace coldspray::mpm
