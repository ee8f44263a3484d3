// The 3D target's case (examples/al-14um-810-3d-fast.yaml, docs/validation/coarsening.md) holds
// what its comment says: the 14 um particle at 810 m/s on the thesis' 30 x 10 um cylinder, a 3D
// quarter at 0.7/0.175 um, the substrate fine in a box of half-width 7 um and depth 3.5 um whose
// corners reach past the contact's rim (8.4 um from the axis), the particle fine below z = 5 um,
// both coarsened twice; the time step fixed at 0.3 of the undeformed critical step.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <variant>

#include "case/load.hpp"

namespace coldspray::case_file {
namespace {

TEST(Fast3dExample, IsTheThesisImpactWithTheDocumentedFineRegions) {
  const Case c =
      load_case(std::string(COLDSPRAY_SOURCE_DIR) + "/examples/al-14um-810-3d-fast.yaml");
  ASSERT_EQ(c.bodies.size(), 2u);
  const Body& particle = c.bodies[0];
  const Body& substrate = c.bodies[1];
  EXPECT_NEAR(std::get<geometry::Sphere>(particle.shape).radius, 7e-6, 1e-12);
  EXPECT_NEAR(particle.velocity.z(), -810.0, 1e-9);
  EXPECT_NEAR(std::get<geometry::Cylinder>(substrate.shape).radius, 15e-6, 1e-12);
  EXPECT_NEAR(std::get<geometry::Cylinder>(substrate.shape).height, 10e-6, 1e-12);
  EXPECT_EQ(c.solver.geometry, Geometry::ThreeD);
  EXPECT_NEAR(c.grid->cell_size, 0.7e-6, 1e-15);
  EXPECT_NEAR(particle.spacing, 0.175e-6, 1e-15);
  EXPECT_EQ(c.grid->faces.at(GridFace::XMin), FaceCondition::Roller);
  EXPECT_EQ(c.grid->faces.at(GridFace::YMin), FaceCondition::Roller);
  ASSERT_TRUE(c.solver.dt_scale);
  EXPECT_DOUBLE_EQ(*c.solver.dt_scale, c.solver.cfl);  // the CFL rule's first step, held

  ASSERT_TRUE(substrate.coarsening);
  EXPECT_EQ(substrate.coarsening->levels, 2);
  const auto& box = std::get<geometry::Box>(substrate.coarsening->fine);
  EXPECT_NEAR(box.max.x(), 7e-6, 1e-12);
  EXPECT_NEAR(box.min.z(), -3.5e-6, 1e-12);
  EXPECT_GT(std::hypot(box.max.x(), box.max.y()), 8.4e-6);  // the corner past the contact's rim

  ASSERT_TRUE(particle.coarsening);
  EXPECT_EQ(particle.coarsening->levels, 2);
  const auto& fine = std::get<geometry::Cylinder>(particle.coarsening->fine);
  EXPECT_NEAR(fine.base_center.z() + fine.height, 5e-6, 1e-12);  // fine below z = 5 um
  EXPECT_GE(fine.radius, 7e-6);                                  // the particle's whole width
}

}  // namespace
}  // namespace coldspray::case_file
