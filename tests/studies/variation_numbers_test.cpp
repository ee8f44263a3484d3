// Issue 52, item 1: a sweep range writes its values as "{:.12g} UNIT", "1e+12 J/m^2" from
// 1e12 on, which was read back as 1 J/m^2; the values now read back as the range's.
#include <gtest/gtest.h>

#include "core/units.hpp"
#include "studies/variation.hpp"

namespace coldspray::studies {
namespace {

TEST(SweepVariation, RangeValuesWithExponentsReadBackWithTheirUnit) {
  const Variation g = parse_variation("bonding.critical_energy=1e+12 J/m^2:3E12J/m^2:+1e012 J/m^2");
  ASSERT_EQ(g.values.size(), 3u);
  EXPECT_EQ(g.values[0], "1e+12 J/m^2");
  const double expected[] = {1e12, 2e12, 3e12};
  for (std::size_t i = 0; i < 3; ++i)
    EXPECT_EQ(units::parse_as(g.values[i], units::kEnergyPerArea), expected[i]) << g.values[i];
  const Variation t = parse_variation("output.snapshot_interval=1e-9 s:3e-9 s:1e-9 s");
  ASSERT_EQ(t.values.size(), 3u);
  EXPECT_EQ(units::parse_as(t.values[2], units::kTime), 3e-9) << t.values[2];
}

}  // namespace
}  // namespace coldspray::studies
