// The two-particle examples of the thesis' §5.2.2 (examples/multi-particle/): each loads, and
// holds what its name and comment say: two 14 um particles at 810 m/s, the first touching the
// substrate, the second's centre 30 um above it and offset along x by the named distance, a
// quarter model without offset and a half model about y = 0 with one, the substrate coarsened
// around both impacts.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <variant>

#include "case/load.hpp"

namespace coldspray::case_file {
namespace {

TEST(MultiParticleExamples, TwoParticlesAtTheThesisOffsets) {
  const std::pair<const char*, double> cases[] = {
      {"0", 0.0}, {"2.5", 2.5}, {"5", 5.0}, {"7.5", 7.5}};
  for (const auto& [name, offset_um] : cases) {
    SCOPED_TRACE(name);
    const Case c = load_case(std::string(COLDSPRAY_SOURCE_DIR) +
                             "/examples/multi-particle/two-particles-" + name + "um.yaml");
    ASSERT_EQ(c.bodies.size(), 3u);
    const auto& bottom = std::get<geometry::Sphere>(c.bodies[0].shape);
    const auto& top = std::get<geometry::Sphere>(c.bodies[1].shape);
    EXPECT_NEAR(bottom.radius, 7e-6, 1e-12);
    EXPECT_NEAR(top.radius, 7e-6, 1e-12);
    EXPECT_NEAR(bottom.center.z(), 7e-6, 1e-12);  // touching the substrate's top, z = 0
    EXPECT_NEAR(top.center.z(), 30e-6, 1e-12);
    EXPECT_NEAR(top.center.x() - bottom.center.x(), offset_um * 1e-6, 1e-12);
    for (int b = 0; b < 2; ++b) EXPECT_NEAR(c.bodies[b].velocity.z(), -810.0, 1e-9);
    EXPECT_EQ(c.bodies[2].name, "substrate");  // highest-id: the substrate's normal (§5.2.3)
    EXPECT_EQ(c.contact.mpm.normal, ContactNormal::HighestId);
    EXPECT_NEAR(c.grid->cell_size, 0.7e-6, 1e-15);
    EXPECT_NEAR(c.bodies[0].spacing, 0.175e-6, 1e-15);
    EXPECT_EQ(c.grid->faces.at(GridFace::YMin), FaceCondition::Roller);
    EXPECT_EQ(c.grid->faces.at(GridFace::XMin),
              offset_um == 0.0 ? FaceCondition::Roller : FaceCondition::Free);
    ASSERT_TRUE(c.bodies[2].coarsening);
    const auto& fine = std::get<geometry::Cylinder>(c.bodies[2].coarsening->fine);
    // The fine region takes in both impacts' 9.1 um.
    EXPECT_LE(fine.base_center.x() - fine.radius, -9.1e-6 + 1e-12);
    EXPECT_GE(fine.base_center.x() + fine.radius, offset_um * 1e-6 + 9.1e-6 - 1e-12);
    EXPECT_NEAR(c.solver.end_time, 90e-9, 1e-18);
  }
}

}  // namespace
}  // namespace coldspray::case_file
