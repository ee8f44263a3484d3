// Issue 52, item 1: the numbers the generated cases write read back to the value given.
#include "setups/case_text.hpp"

#include <gtest/gtest.h>

#include "core/units.hpp"

namespace coldspray::setups {
namespace {

// What the generated cases write, setups/case_text.cpp, reads back to the value given: 12
// significant digits, the most a value typed on the command line is taken to have.
TEST(CaseText, GeneratedCaseNumbersReadBack) {
  for (const double v : {1e12, 1e-7, 2.8e5, -1.5e-3, 123456789012.0, 1e100, 4.2e-300, 810.0}) {
    SCOPED_TRACE(number(v));
    EXPECT_EQ(units::parse_as(number(v), units::kDimensionless), v);
    EXPECT_EQ(units::parse_as(number(v) + " J/m^2", units::kEnergyPerArea), v);
  }
  for (const char* typed : {"0.175um", "1e+3um", "22um", "1.5e-3um", "123.456789012um"}) {
    SCOPED_TRACE(typed);
    const double metres = units::parse_as(typed, units::kLength);
    EXPECT_EQ(units::parse_as(um(metres), units::kLength), metres) << um(metres);
  }
}

}  // namespace
}  // namespace coldspray::setups
