// The contact normal of eq 3.30 at a flat interface: two discs stacked on the z axis touch on the
// plane z = 0, so away from their rims every pair's normal there is the z axis, in 3D and in
// r-z. In r-z a point's mass is a ring's, 2 pi r rho A; weighing the gradient with it tilted the
// normal towards the axis by atan(h / 2r) (27 degrees at r = h, 6 at r = 5h), which made a
// frictionless interface resist radial slip (mpm/phases.hpp, PointContribution::m_normal).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"

namespace coldspray::mpm {
namespace {

struct InterfaceNormals {
  int pairs = 0;           // pairs with a normal at nodes on z = 0, r <= R - 2h
  double largest_lateral;  // their largest |n_x|, |n_y| (r-z: n_r)
};

InterfaceNormals interface_normals(const std::string& geometry) {
  const double radius = 6e-6;
  const case_file::Case c =
      case_file::load_case(std::string(COLDSPRAY_TEST_DATA) + "/cases/stacked-discs.yaml",
                           {{"solver.geometry", geometry}});
  State s = build_state(c);
  s.dt = stable_time_step(s, c.solver.cfl);
  step_to_contact(s);
  const GridLayout& L = s.layout;
  const ContactNodes& cn = s.contact;
  InterfaceNormals out{0, 0.0};
  for (std::size_t slot = 0; slot < cn.size(); ++slot) {
    const auto sl = static_cast<std::int32_t>(slot);
    if (cn.body_count(sl) != 2) continue;
    const std::size_t n = cn.node(sl);
    const int i = static_cast<int>(n % L.nodes[0]);
    const int j = static_cast<int>((n / L.nodes[0]) % L.nodes[1]);
    const int k = static_cast<int>(n / (static_cast<std::size_t>(L.nodes[0]) * L.nodes[1]));
    const double x = L.coordinate(0, i), y = L.nodes[1] == 1 ? 0.0 : L.coordinate(1, j);
    if (std::abs(L.coordinate(2, k)) > 1e-3 * L.h || std::hypot(x, y) > radius - 2.0 * L.h)
      continue;
    const std::size_t pair = ContactNodes::pair(sl, 0, 1);
    if (cn.pair_master[pair] < 0) continue;
    ++out.pairs;
    EXPECT_NEAR(cn.pair_normal[2][pair], 1.0, 1e-12) << "node at r = " << std::hypot(x, y);
    out.largest_lateral = std::max({out.largest_lateral, std::abs(cn.pair_normal[0][pair]),
                                    std::abs(cn.pair_normal[1][pair])});
  }
  return out;
}

TEST(ContactNormal, FlatInterfaceIsAxialInRz) {
  const InterfaceNormals rz = interface_normals("axisymmetric");
  EXPECT_EQ(rz.pairs, 11);  // the nodes at r = 0, 0.5, ..., 5 um
  EXPECT_LT(rz.largest_lateral, 1e-12);
}

TEST(ContactNormal, FlatInterfaceIsAxialIn3d) {
  const InterfaceNormals full = interface_normals("3d");
  EXPECT_EQ(full.pairs, 317);  // the grid nodes within 10 cells of the axis (Gauss circle N(10))
  EXPECT_LT(full.largest_lateral, 1e-12);
}

}  // namespace
}  // namespace coldspray::mpm
