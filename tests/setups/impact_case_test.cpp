// The impact set-up's substrate (setups/impact_case.hpp): thesis Table 5.3 reproduced, and
// interpolated inside it and scaled outside.
#include "setups/impact_case.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace coldspray::setups {
namespace {

TEST(ImpactSubstrate, ReproducesThesisTable53) {
  const double table[][2] = {{14, 30}, {18, 36}, {22, 44}, {26, 46}, {30, 50}};
  for (const auto& row : table) {
    const SubstrateSize s = substrate_size(row[0] * 1e-6, SetUp::Thesis);
    EXPECT_DOUBLE_EQ(s.diameter, row[1] * 1e-6) << row[0];
    EXPECT_DOUBLE_EQ(s.height, 10e-6) << row[0];
    // Diameters a unit conversion leaves a hair off the table's (3e-5 / 1e-6 = 30.000000000000004)
    // are still the table's.
    EXPECT_DOUBLE_EQ(substrate_size(std::nextafter(row[0] * 1e-6, 1.0), SetUp::Thesis).diameter,
                     row[1] * 1e-6);
  }
}

TEST(ImpactSubstrate, InterpolatesInsideTheTableAndScalesOutside) {
  EXPECT_DOUBLE_EQ(substrate_size(20e-6, SetUp::Thesis).diameter,
                   40e-6);  // between 36 and 44
  EXPECT_DOUBLE_EQ(substrate_size(28e-6, SetUp::Thesis).diameter,
                   48e-6);  // between 46 and 50
  // Below 14 um the 14 um case scaled: 7 um -> 15 um; 4 um -> 8.57 -> 8.6 um (0.1 um up).
  EXPECT_DOUBLE_EQ(substrate_size(7e-6, SetUp::Thesis).diameter, 15e-6);
  EXPECT_DOUBLE_EQ(substrate_size(4e-6, SetUp::Thesis).diameter, 8.6e-6);
  EXPECT_DOUBLE_EQ(substrate_size(4e-6, SetUp::Thesis).height, 10e-6);
  // Above 30 um: 2 d across, max(10 um, d/3) high.
  EXPECT_DOUBLE_EQ(substrate_size(45e-6, SetUp::Thesis).diameter, 90e-6);
  EXPECT_DOUBLE_EQ(substrate_size(45e-6, SetUp::Thesis).height, 15e-6);
  EXPECT_DOUBLE_EQ(substrate_size(38e-6, SetUp::Thesis).diameter, 76e-6);
  EXPECT_DOUBLE_EQ(substrate_size(38e-6, SetUp::Thesis).height, 12.7e-6);
}

}  // namespace
}  // namespace coldspray::setups
