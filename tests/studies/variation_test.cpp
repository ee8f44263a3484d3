// Parsing `--vary` and expanding the combinations of a sweep.
#include "studies/variation.hpp"

#include <gtest/gtest.h>

#include "core/error.hpp"
#include "core/units.hpp"

namespace coldspray::studies {
namespace {

TEST(SweepVariation, ListsSplitOutsideBrackets) {
  const Variation v = parse_variation("bodies.particle.velocity=[0, 0, -700 m/s],[0,0,-800 m/s]");
  EXPECT_EQ(v.key, "bodies.particle.velocity");
  ASSERT_EQ(v.values.size(), 2u);
  EXPECT_EQ(v.values[0], "[0, 0, -700 m/s]");
  EXPECT_EQ(v.values[1], "[0,0,-800 m/s]");
  EXPECT_EQ(parse_variation("grid.cell_size=0.7um, 1.0 um").values.at(1), "1.0 um");
}

TEST(SweepVariation, RangesIncludeStopAndKeepTheUnit) {
  const Variation d = parse_variation("solver.cfl=0.1:0.3:0.1");
  ASSERT_EQ(d.values.size(), 3u);  // 0.3 is reached although 0.1 + 0.1 + 0.1 > 0.3
  EXPECT_EQ(d.values[2], "0.3");
  const Variation g = parse_variation("bonding.critical_energy=500 J/m^2:2 kJ/m^2:500J/m^2");
  ASSERT_EQ(g.values.size(), 4u);
  EXPECT_DOUBLE_EQ(units::parse_as(g.values[3], units::kEnergyPerArea), 2000.0);
  const Variation r =
      parse_variation("bonding.critical_energy_rate=1 J/m^2/us:3 J/m^2/us:1 J/m^2/us");
  ASSERT_EQ(r.values.size(), 3u);
  EXPECT_DOUBLE_EQ(units::parse_as(r.values[1], units::kEnergyPerAreaPerTime), 2e6);
}

TEST(SweepVariation, BadTextNamesVary) {
  for (const char* bad : {"solver.cfl", "=1,2", "solver.cfl=0.1:0.3:0", "solver.cfl=0.3:0.1:0.1",
                          "grid.cell_size=1 um:2 s:1 um", "solver.cfl=1,,2"}) {
    SCOPED_TRACE(bad);
    try {
      parse_variation(bad);
      ADD_FAILURE() << "no error";
    } catch (const InputError& e) {
      EXPECT_EQ(e.where(), std::string("--vary ") + bad);
    }
  }
}

TEST(SweepVariation, CombinationsVaryTheLastKeyFastest) {
  const auto combos = combinations({parse_variation("a=1,2"), parse_variation("b=x,y,z")});
  ASSERT_EQ(combos.size(), 6u);
  EXPECT_EQ(combos[0][0].value, "1");
  EXPECT_EQ(combos[0][1].value, "x");
  EXPECT_EQ(combos[1][1].value, "y");
  EXPECT_EQ(combos[3][0].value, "2");
  EXPECT_EQ(combos[5][1].value, "z");
}

}  // namespace
}  // namespace coldspray::studies
