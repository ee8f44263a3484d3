// Two discs stacked on the z axis (tests/data/cases/stacked-discs.yaml) touch on the plane z = 0:
// at the contact nodes on that plane away from the rims,
// - the contact normal of eq 3.30 is the z axis, in 3D and in r-z. In r-z a point's mass is a
//   ring's, 2 pi r rho A; weighing the gradient with it tilted the normal towards the axis by
//   atan(h / 2r) (27 degrees at r = h, 6 at r = 5h), which made a frictionless interface resist
//   radial slip (mpm/phases.hpp, map_bodies_to_contact_nodes);
// - eq 4.6's nodal D_bond of surface points that all carry the same D_bond is that D_bond by
//   weight (the default) in both geometries, while by count (the thesis' divisor) it depends on
//   how many points of small weight the node's support holds, which differs between the r-z
//   section and the 3D patch (docs/bonding.md).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "case/load.hpp"
#include "mpm/contact.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"

namespace coldspray::mpm {
namespace {

// Builds the discs in `geometry`, gives their surface points D_bond = `bond`, runs the step up to
// the contact decision and calls f(slot, r) for each two-body contact node on z = 0 within
// R - 2h of the axis (r-z: not the ghost layer beyond it).
void for_each_interface_node(
    const std::string& geometry, double bond,
    const std::function<void(const ContactNodes&, std::int32_t, double)>& f) {
  const double radius = 6e-6;
  const case_file::Case c =
      case_file::load_case(std::string(COLDSPRAY_TEST_DATA) + "/cases/stacked-discs.yaml",
                           {{"solver.geometry", geometry}, {"bonding.model", "energy"}});
  State s = build_state(c);
  for (std::size_t p = 0; p < s.points.size(); ++p)
    s.points.bond[p] = s.points.surface[p] ? bond : 0.0;
  s.dt = stable_time_step(s, c.solver.cfl);
  step_to_contact(s);
  const GridLayout& L = s.layout;
  const ContactNodes& cn = s.contact;
  for (std::size_t slot = 0; slot < cn.size(); ++slot) {
    const auto sl = static_cast<std::int32_t>(slot);
    if (cn.body_count(sl) != 2) continue;
    const std::size_t n = cn.node(sl);
    const int i = static_cast<int>(n % L.nodes[0]);
    const int j = static_cast<int>((n / L.nodes[0]) % L.nodes[1]);
    const int k = static_cast<int>(n / (static_cast<std::size_t>(L.nodes[0]) * L.nodes[1]));
    const double x = L.coordinate(0, i), y = L.nodes[1] == 1 ? 0.0 : L.coordinate(1, j);
    if (L.nodes[1] == 1 && x < 0.0) continue;
    const double r = std::hypot(x, y);
    if (std::abs(L.coordinate(2, k)) > 1e-3 * L.h || r > radius - 2.0 * L.h) continue;
    f(cn, sl, r);
  }
}

struct InterfaceNormals {
  int pairs = 0;                 // pairs with a normal
  double largest_lateral = 0.0;  // their largest |n_x|, |n_y| (r-z: n_r)
};

InterfaceNormals interface_normals(const std::string& geometry) {
  InterfaceNormals out;
  for_each_interface_node(geometry, 0.0, [&](const ContactNodes& cn, std::int32_t sl, double r) {
    const std::size_t pair = ContactNodes::pair(sl, 0, 1);
    if (cn.pair_master[pair] < 0) return;
    ++out.pairs;
    EXPECT_NEAR(cn.pair_normal[2][pair], 1.0, 1e-12) << "node at r = " << r;
    out.largest_lateral = std::max({out.largest_lateral, std::abs(cn.pair_normal[0][pair]),
                                    std::abs(cn.pair_normal[1][pair])});
  });
  return out;
}

TEST(FlatInterface, NormalIsAxialInRz) {
  const InterfaceNormals rz = interface_normals("axisymmetric");
  EXPECT_EQ(rz.pairs, 11);  // the nodes at r = 0, 0.5, ..., 5 um
  EXPECT_LT(rz.largest_lateral, 1e-12);
}

TEST(FlatInterface, NormalIsAxialIn3d) {
  const InterfaceNormals full = interface_normals("3d");
  EXPECT_EQ(full.pairs, 317);  // the grid nodes within 10 cells of the axis (Gauss circle N(10))
  EXPECT_LT(full.largest_lateral, 1e-12);
}

struct NodalRange {
  double lowest = INFINITY, highest = -INFINITY;
  int nodes = 0;
};

// Eq 4.7's nodal D_bond over the interface nodes, every surface point at D_bond = 0.5.
NodalRange interface_bond(const std::string& geometry, case_file::NodalAverage average) {
  NodalRange out;
  for_each_interface_node(geometry, 0.5, [&](const ContactNodes& cn, std::int32_t sl, double) {
    const double d = nodal_bond(cn, sl, 0, 1, average);
    out.lowest = std::min(out.lowest, d);
    out.highest = std::max(out.highest, d);
    ++out.nodes;
  });
  return out;
}

TEST(FlatInterface, ByWeightAUniformInterfaceReadsItsBondInRzAnd3d) {
  for (const char* geometry : {"axisymmetric", "3d"}) {
    const NodalRange r = interface_bond(geometry, case_file::NodalAverage::Weight);
    EXPECT_GT(r.nodes, 10) << geometry;
    EXPECT_NEAR(r.lowest, 0.5, 1e-12) << geometry;
    EXPECT_NEAR(r.highest, 0.5, 1e-12) << geometry;
  }
}

TEST(FlatInterface, ByCountTheNodalBondDependsOnTheGeometry) {
  const NodalRange rz = interface_bond("axisymmetric", case_file::NodalAverage::Count);
  const NodalRange full = interface_bond("3d", case_file::NodalAverage::Count);
  std::printf("by count: r-z %.4f-%.4f, 3D %.4f-%.4f\n", rz.lowest, rz.highest, full.lowest,
              full.highest);
  EXPECT_LT(rz.highest, 0.5);
  EXPECT_LT(full.highest, rz.lowest);  // the 3D patch holds more points of small weight
}

}  // namespace
}  // namespace coldspray::mpm
