// Eq 4.6's nodal D_bond on a flat interface whose surface points all carry the same D_bond: by
// weight (the default) every interface node reads that D_bond, in r-z and in 3D alike; by count
// (the thesis' divisor) the value depends on how many points with small weights the node's
// support holds, which differs between the r-z section and the 3D patch (docs/bonding.md).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "case/load.hpp"
#include "mpm/contact.hpp"
#include "mpm/setup.hpp"
#include "mpm/stepper.hpp"

namespace coldspray::mpm {
namespace {

struct NodalRange {
  double lowest = INFINITY, highest = -INFINITY;
  int nodes = 0;
};

// Over the contact nodes on z = 0 within R - 2h of the axis, eq 4.7's nodal D_bond after the
// surface points of both discs were given D_bond = 0.5.
NodalRange interface_bond(const std::string& geometry, case_file::NodalAverage average) {
  const case_file::Case c =
      case_file::load_case(std::string(COLDSPRAY_TEST_DATA) + "/cases/stacked-discs.yaml",
                           {{"solver.geometry", geometry}, {"bonding.model", "energy"}});
  State s = build_state(c);
  for (std::size_t p = 0; p < s.points.size(); ++p)
    s.points.bond[p] = s.points.surface[p] ? 0.5 : 0.0;
  s.dt = stable_time_step(s, c.solver.cfl);
  step_to_contact(s);
  const GridLayout& L = s.layout;
  const ContactNodes& cn = s.contact;
  NodalRange out;
  for (std::size_t slot = 0; slot < cn.size(); ++slot) {
    const auto sl = static_cast<std::int32_t>(slot);
    if (cn.body_count(sl) != 2) continue;
    const std::size_t n = cn.node(sl);
    const int i = static_cast<int>(n % L.nodes[0]);
    const int j = static_cast<int>((n / L.nodes[0]) % L.nodes[1]);
    const int k = static_cast<int>(n / (static_cast<std::size_t>(L.nodes[0]) * L.nodes[1]));
    const double x = L.coordinate(0, i), y = L.nodes[1] == 1 ? 0.0 : L.coordinate(1, j);
    if (x < 0.0 && L.nodes[1] == 1) continue;  // r-z: the ghost layer beyond the axis
    if (std::abs(L.coordinate(2, k)) > 1e-3 * L.h || std::hypot(x, y) > 6e-6 - 2.0 * L.h) continue;
    const double d = nodal_bond(cn, sl, 0, 1, average);
    out.lowest = std::min(out.lowest, d);
    out.highest = std::max(out.highest, d);
    ++out.nodes;
  }
  return out;
}

TEST(NodalBondOnFlatInterface, ByWeightAUniformInterfaceReadsItsValueInRzAnd3d) {
  for (const char* geometry : {"axisymmetric", "3d"}) {
    const NodalRange r = interface_bond(geometry, case_file::NodalAverage::Weight);
    EXPECT_GT(r.nodes, 10) << geometry;
    EXPECT_NEAR(r.lowest, 0.5, 1e-12) << geometry;
    EXPECT_NEAR(r.highest, 0.5, 1e-12) << geometry;
  }
}

TEST(NodalBondOnFlatInterface, ByCountTheValueDependsOnTheGeometry) {
  const NodalRange rz = interface_bond("axisymmetric", case_file::NodalAverage::Count);
  const NodalRange full = interface_bond("3d", case_file::NodalAverage::Count);
  std::printf("by count: r-z %.4f-%.4f, 3D %.4f-%.4f\n", rz.lowest, rz.highest, full.lowest,
              full.highest);
  EXPECT_LT(rz.highest, 0.5);
  EXPECT_LT(full.highest, rz.lowest);  // the 3D patch holds more points of small weight
}

}  // namespace
}  // namespace coldspray::mpm
