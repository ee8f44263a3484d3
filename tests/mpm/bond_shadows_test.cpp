// Bond shadows (mpm/bond_shadows.hpp) keep one column per surface point: when points leave the
// run (mpm/departures.hpp) their columns go, and every other surface point keeps its D_bond.
#include "mpm/bond_shadows.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "mpm/erase_indices.hpp"

namespace coldspray::mpm {
namespace {

TEST(MpmBondShadows, PointsThatLeaveTakeTheirColumnsAndTheOthersKeepTheirs) {
  bodies::Points P;
  P.resize(6);
  const std::uint8_t surface[6] = {1, 0, 1, 1, 0, 1};
  for (std::size_t p = 0; p < 6; ++p) P.surface[p] = surface[p];
  case_file::Bonding law;
  law.model = case_file::BondingModel::Energy;
  case_file::Bonding other = law;
  other.critical_energy *= 2.0;
  BondShadows shadows;
  shadows.follow({bonding::BondLaw::from_case(law, 1e-6), bonding::BondLaw::from_case(other, 1e-6)},
                 P);
  // A von Mises stress of (p + 1) x 100 MPa: each surface point's D_bond its own.
  auto grow = [&](std::size_t p, double sigma) {
    shadows.grow(p, Eigen::Vector3d(sigma, 0.0, 0.0).asDiagonal(), 0.01, Eigen::Vector3d::UnitZ(),
                 1e-11);
  };
  for (std::size_t p = 0; p < 6; ++p)
    if (surface[p]) grow(p, 1e8 * static_cast<double>(p + 1));
  shadows.write_bond(1, P);
  const std::vector<double> before = P.bond;
  ASSERT_GT(before[5], before[3]);
  ASSERT_GT(before[3], before[2]);

  const std::vector<std::size_t> gone = {0, 3, 4};
  shadows.remove_points(gone);
  P.for_each_array([&](auto& v) { erase_indices(v, gone); });
  shadows.clear_bond(P);
  shadows.write_bond(1, P);
  EXPECT_EQ(P.bond, (std::vector<double>{0.0, before[2], before[5]}));

  // Growing the point now at index 1 (2 before) grows its own column only.
  grow(1, 1e8);
  shadows.write_bond(1, P);
  EXPECT_GT(P.bond[1], before[2]);
  EXPECT_EQ(P.bond[2], before[5]);
  shadows.clear_bond(P);
  EXPECT_EQ(P.bond, (std::vector<double>(3, 0.0)));
}

}  // namespace
}  // namespace coldspray::mpm
