#include "core/units.hpp"

#include <gtest/gtest.h>

#include <string>

#include "core/error.hpp"

namespace coldspray::units {
namespace {

struct Case {
  const char* text;
  double si;  // by hand
  Dimension dimension;
};

// Each unit converts exactly (the decimal exponent is shifted before rounding), so the values
// compare equal to the hand-converted literals.
TEST(ParseQuantity, ConvertsToSiByHand) {
  const Case cases[] = {
      {"14 um", 14e-6, kLength},
      {"810 m/s", 810.0, kVelocity},
      {"-810 m/s", -810.0, kVelocity},
      {"80 ns", 80e-9, kTime},
      {"1.5 GPa", 1.5e9, kPressure},
      {"148.4 MPa", 148.4e6, kPressure},
      {"298 K", 298.0, kTemperature},
      {"2700 kg/m^3", 2700.0, kDensity},
      {"1503.74 J/m^2", 1503.74, kEnergyPerArea},
      {"2.271 J/m^2/us", 2.271e6, kEnergyPerAreaPerTime},
      {"896 J/kg/K", 896.0, kSpecificHeat},
      {"1 1/s", 1.0, kRate},
      {"1e7 1/s", 1e7, kRate},
      {"4.48e-23 kg", 4.48e-23, kMass},
      {"1e-3 m", 1e-3, kLength},
      {"0.175 um", 0.175e-6, kLength},
      {"5 mm", 5e-3, kLength},
      {"3 cm", 3e-2, kLength},
      {"2 km", 2e3, kLength},
      {"7 nm", 7e-9, kLength},
      {"2 g", 2e-3, kMass},
      {"3 mg", 3e-6, kMass},
      {"10 ms", 10e-3, kTime},
      {"2 kN", 2e3, kForce},
      {"5 mJ", 5e-3, kEnergy},
      {"3 MW", 3e6, kEnergy / kTime},
      {"1 kg*m/s^2", 1.0, kForce},
      {"2 N*m", 2.0, kEnergy},
      {"4 m^-1", 4.0, kDimensionless / kLength},
      {"1 J/kg*K", 1.0, kEnergy / kMass * kTemperature},  // left to right: (J/kg)*K
      {"7 \u00b5m", 7e-6, kLength},                       // micro sign
      {"7 \u03bcm", 7e-6, kLength},                       // Greek mu
      {"  14   um ", 14e-6, kLength},
      {"14um", 14e-6, kLength},
      {"+3 K", 3.0, kTemperature},
      {"2.5e3 kg / m^3", 2500.0, kDensity},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.text);
    const Quantity q = parse_quantity(c.text);
    EXPECT_EQ(q.value, c.si);
    EXPECT_EQ(q.dimension, c.dimension);
  }
}

TEST(ParseQuantity, BareNumberIsDimensionlessSi) {
  const Quantity q = parse_quantity("0.3");
  EXPECT_EQ(q.value, 0.3);
  EXPECT_EQ(q.dimension, kDimensionless);
  EXPECT_EQ(parse_quantity("-1.75e-07").value, -1.75e-07);
}

std::string unit_error(const std::string& text) {
  try {
    parse_quantity(text);
  } catch (const UnitError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no UnitError for '" << text << "'";
  return "";
}

TEST(ParseQuantity, RejectsMalformedTextWithClearMessages) {
  const std::pair<const char*, const char*> cases[] = {
      {"", "empty value"},
      {"   ", "empty value"},
      {"fast", "'fast' is not a number"},
      {"um", "'um' is not a number"},
      {"14 furlongs", "unknown unit 'furlongs'"},
      {"1 mK", "unknown unit 'mK'"},
      {"14 m/", "ends early"},
      {"14 m s", "unexpected 's'"},
      {"14 m**2", "unexpected '*'"},
      {"1 m^x", "'^' must be followed by a non-zero integer power"},
      {"1 m^0", "non-zero integer power"},
      {"1 1", "'1' may only start a unit written as 1/UNIT"},
      {"1 s/1", "unexpected '1'"},
      {"1,5 m", "unexpected ','"},
      {"nan", "finite"},
      {"inf m", "finite"},
      {"1e999 m", "out of range"},
      {"1e300 GPa", "out of range"},
  };
  for (const auto& [text, message] : cases) {
    SCOPED_TRACE(text);
    EXPECT_NE(unit_error(text).find(message), std::string::npos) << unit_error(text);
  }
}

TEST(ParseQuantity, RejectsTemperatureScalesOtherThanKelvin) {
  for (const char* text : {"20 degC", "20 C", "68 degF", "20 \u00b0C"}) {
    SCOPED_TRACE(text);
    const std::string message = unit_error(text);
    EXPECT_NE(message.find("temperatures are given in K only"), std::string::npos) << message;
  }
}

TEST(ParseAs, ChecksTheDimension) {
  EXPECT_EQ(parse_as("14 um", kLength), 14e-6);
  EXPECT_EQ(parse_as("810 m/s", kVelocity), 810.0);
  EXPECT_EQ(parse_as("0.3", kDimensionless), 0.3);
  try {
    parse_as("14 m/s", kLength);
    FAIL() << "no UnitError";
  } catch (const UnitError& e) {
    EXPECT_NE(std::string(e.what()).find("expected a length (m), got a velocity (m/s)"),
              std::string::npos)
        << e.what();
  }
  try {
    parse_as("1 m", kDimensionless);
    FAIL() << "no UnitError";
  } catch (const UnitError& e) {
    EXPECT_NE(std::string(e.what()).find("expected a dimensionless number, got a length (m)"),
              std::string::npos)
        << e.what();
  }
}

TEST(ParseAs, TakesABareNumberAsSiOfTheExpectedDimension) {
  EXPECT_EQ(parse_as("1.75e-07", kLength), 1.75e-07);
  EXPECT_EQ(parse_as("2.6e+10", kPressure), 2.6e10);
  EXPECT_EQ(parse_as("298", kTemperature), 298.0);
}

TEST(ParseAs, OneOverSecondIsARateNotABareNumber) {
  EXPECT_EQ(parse_as("1 1/s", kRate), 1.0);
  EXPECT_THROW(parse_as("1 1/s", kDimensionless), UnitError);
}

TEST(SiUnit, NamesCommonDimensions) {
  EXPECT_EQ(si_unit(kDimensionless), "-");
  EXPECT_EQ(si_unit(kLength), "m");
  EXPECT_EQ(si_unit(kVelocity), "m/s");
  EXPECT_EQ(si_unit(kPressure), "Pa");
  EXPECT_EQ(si_unit(kDensity), "kg/m^3");
  EXPECT_EQ(si_unit(kEnergyPerAreaPerTime), "J/m^2/s");
  EXPECT_EQ(si_unit(kSpecificHeat), "J/kg/K");
  EXPECT_EQ(si_unit(kRate), "1/s");
  EXPECT_EQ(si_unit(kLength / kTime.pow(2)), "m/s^2");
  EXPECT_EQ(si_unit(kDimensionless / kLength), "1/m");
  EXPECT_EQ(si_unit(kMass * kLength.pow(2)), "kg*m^2");
}

TEST(DimensionName, NamesCommonDimensionsAndFallsBackToTheUnit) {
  EXPECT_EQ(dimension_name(kLength), "length");
  EXPECT_EQ(dimension_name(kVelocity), "velocity");
  EXPECT_EQ(dimension_name(kPressure), "pressure");
  EXPECT_EQ(dimension_name(kTemperature), "temperature");
  EXPECT_EQ(dimension_name(kLength / kTime.pow(2)), "m/s^2");
}

// Powers used to wrap around in int: um^2147483647*um^2147483647*um^3 came out as plain um
// (and UBSan reported the overflow). Powers of units and of the base dimensions are bounded.
TEST(ParseQuantity, RefusesPowersThatCouldOverflow) {
  auto message = [](const char* text) {
    try {
      parse_quantity(text);
    } catch (const UnitError& e) {
      return std::string(e.what());
    }
    return std::string("accepted");
  };
  EXPECT_NE(message("7 um^2147483647*um^2147483647*um^3").find("between -12 and 12"),
            std::string::npos);
  EXPECT_NE(message("7 m^99999999999").find("between -12 and 12"), std::string::npos);
  EXPECT_NE(message("7 m^13").find("between -12 and 12"), std::string::npos);
  std::string many = "7 m";
  for (int i = 0; i < 12; ++i) many += "*m";
  EXPECT_NE(message(many.c_str()).find("the unit's powers"), std::string::npos);
  std::string scaled = "7 1";
  for (int i = 0; i < 200; ++i) scaled += "/um*m";
  EXPECT_NE(message(scaled.c_str()).find("scale is out of range"), std::string::npos);
  EXPECT_EQ(parse_quantity("1 m^12").dimension, kLength.pow(12));
  EXPECT_EQ(parse_quantity("1 m^-12").dimension, kLength.pow(-12));
}

}  // namespace
}  // namespace coldspray::units
