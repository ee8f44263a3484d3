// A body reaches only the grid nodes where its points weigh (mpm/phases.hpp, map_points_to_grid).
// Two discs touching on z = 0 (tests/data/cases/stacked-discs.yaml: cell h = 0.5 um, spacing
// 0.125 um, so GIMP's a = 1/8): the lowest points of the upper disc sit at z = h/8, whose
// three-node support runs from z = -h to z = h, but the node at z = -h is 9h/8 = (1 + a) h away,
// where the weight and its gradient are zero. Counting it, each disc "reached" the layer beyond
// the plane, and the contact nodes were the three layers z = -h, 0, h, with entries of no mass.
// Now they are the plane's layer alone, and every body at a contact node has mass there.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "case/load.hpp"
#include "mpm/contact.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"

namespace coldspray::mpm {
namespace {

void expect_contact_on_the_plane_alone(const std::string& geometry) {
  const case_file::Case c =
      case_file::load_case(std::string(COLDSPRAY_TEST_DATA) + "/cases/stacked-discs.yaml",
                           {{"solver.geometry", geometry}});
  State s = build_state(c);
  s.dt = stable_time_step(s, c.solver.cfl);
  step_to_contact(s);
  const GridLayout& L = s.layout;
  const ContactNodes& cn = s.contact;
  ASSERT_GT(cn.size(), 0u);
  std::set<long> layers;
  for (std::size_t slot = 0; slot < cn.size(); ++slot) {
    const auto sl = static_cast<std::int32_t>(slot);
    const std::size_t n = cn.node(sl);
    const int k = static_cast<int>(n / (static_cast<std::size_t>(L.nodes[0]) * L.nodes[1]));
    layers.insert(std::lround(L.coordinate(2, k) / L.h));
    for (int e = 0; e < cn.body_count(sl); ++e)
      EXPECT_GT(cn.mass[ContactNodes::flat(sl, e)], 0.0) << "node " << n << ", entry " << e;
  }
  EXPECT_EQ(layers, std::set<long>{0}) << geometry;
}

TEST(ContactReach, TwoDiscsShareOnlyTheNodesOnTheirInterfaceInRz) {
  expect_contact_on_the_plane_alone("axisymmetric");
}

TEST(ContactReach, TwoDiscsShareOnlyTheNodesOnTheirInterfaceIn3d) {
  expect_contact_on_the_plane_alone("3d");
}

}  // namespace
}  // namespace coldspray::mpm
