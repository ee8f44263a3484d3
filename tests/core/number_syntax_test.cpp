// Issue 52, item 1: every number is read as written. "1e+12 J/m^2" was read as 1 J/m^2 (the
// exponent of a number with a unit went through an integer from_chars that refuses '+'), and
// "+-3" as -3. The accepted syntax is docs/input-reference.md, "Quantities and units".
#include <gtest/gtest.h>

#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <random>
#include <string>
#include <tuple>
#include <utility>

#include "core/error.hpp"
#include "core/units.hpp"

namespace coldspray::units {
namespace {

struct Form {
  const char* text;
  double si;  // the literal of the final SI value: the compiler rounds it once, as the parser must
};

// Bit for bit: -0.0 and 0.0 compare equal with ==.
::testing::AssertionResult same_double(double a, double b) {
  if (a == b && std::signbit(a) == std::signbit(b)) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure() << a << " is not " << b;
}

TEST(NumberSyntax, EveryWrittenFormReadsAsItsValue) {
  const Form forms[] = {
      {"1e12", 1e12},
      {"1e+12", 1e12},
      {"1E12", 1e12},
      {"1E+12", 1e12},
      {"1e-3", 1e-3},
      {"1.5e-3", 1.5e-3},
      {"1.5E+03", 1.5e3},
      {"1.5e+003", 1.5e3},
      {"1e+007", 1e7},
      {"1e-007", 1e-7},
      {"+3", 3.0},
      {".5", 0.5},
      {"5.", 5.0},
      {"-.5e-3", -0.5e-3},
      {"+1.000000e+12", 1e12},
      {"-1.250000E-07", -1.25e-7},
      {"0012.50", 12.5},
      {"  2.5  ", 2.5},
      {"1e0", 1.0},
      {"1e+0", 1.0},
      {"0e-400", 0.0},
      {"0.0e+99999999999", 0.0},
      {"1e0000000000000000000000005", 1e5},
      {"2.6e+10", 2.6e10},
      {"1.75e-07", 1.75e-7},
  };
  for (const Form& f : forms) {
    SCOPED_TRACE(f.text);
    const Quantity q = parse_quantity(f.text);
    EXPECT_TRUE(same_double(q.value, f.si));
    EXPECT_EQ(q.dimension, kDimensionless);
  }
}

TEST(NumberSyntax, EveryWrittenFormWithAUnitReadsAsItsSiValue) {
  const struct {
    const char* text;
    double si;
    Dimension dimension;
  } forms[] = {
      {"1e12J/m^2", 1e12, kEnergyPerArea},
      {"1e+12 J/m^2", 1e12, kEnergyPerArea},
      {"1E+12 J/m^2", 1e12, kEnergyPerArea},
      {"1e+3 J/m^2", 1e3, kEnergyPerArea},
      {"1e+3 um", 1e-3, kLength},
      {"1.5e-3 um", 1.5e-9, kLength},
      {"1.5E+03 um", 1.5e-3, kLength},
      {"+1.5e+3 MPa", 1.5e9, kPressure},
      {"2.8e+5 J/m^2/us", 2.8e11, kEnergyPerAreaPerTime},
      {"2.8e+05J/m^2/us", 2.8e11, kEnergyPerAreaPerTime},
      {"8e+08 1/s", 8e8, kRate},
      {"1e+007 ns", 1e-2, kTime},
      {"1e-07 km", 1e-4, kLength},
      {".5 um", 0.5e-6, kLength},
      {"5. um", 5e-6, kLength},
      {"+3 K", 3.0, kTemperature},
      {"  -7.5e+2 m/s  ", -750.0, kVelocity},
      {"1e310 um", 1e304, kLength},    // the SI value is in range: the unit is applied first
      {"1e-330 Gm", 1e-321, kLength},  // subnormal SI values are kept
      {"0e-400 um", 0.0, kLength},
      {"-0 um", -0.0, kLength},
      {"-0.0 m", -0.0, kLength},
  };
  for (const auto& f : forms) {
    SCOPED_TRACE(f.text);
    const Quantity q = parse_quantity(f.text);
    EXPECT_TRUE(same_double(q.value, f.si));
    EXPECT_EQ(q.dimension, f.dimension);
    EXPECT_TRUE(same_double(parse_as(f.text, f.dimension), f.si));
  }
  EXPECT_TRUE(same_double(parse_quantity("-0.0").value, -0.0));
}

std::string error_of(const std::string& text) {
  try {
    const Quantity q = parse_quantity(text);
    return "accepted as " + std::to_string(q.value);
  } catch (const UnitError& e) {
    return e.what();
  }
}

// Whatever is not a number with an optional unit is an error, never another number.
TEST(NumberSyntax, RefusesMalformedNumbers) {
  const std::pair<const char*, const char*> refused[] = {
      {"1e", "'1e' is not a number: 'e' must be followed by a whole exponent"},
      {"1e+", "is not a number: 'e' must be followed"},
      {"1e-", "is not a number: 'e' must be followed"},
      {"1e++3", "is not a number: 'e' must be followed"},
      {"1e+-3", "is not a number: 'e' must be followed"},
      {"1e 3", "is not a number: 'e' must be followed"},
      {"1e+ 3 um", "is not a number: 'e' must be followed"},
      {"1E um", "is not a number: 'e' must be followed"},
      {"1em", "is not a number: 'e' must be followed"},
      {"1e3.5", "'1e3.5' is not a number"},
      {"1e3e2", "'1e3e2' is not a number"},
      {"1.2.3", "'1.2.3' is not a number"},
      {"1+2", "'1+2' is not a number"},
      {"1-2 m", "'1-2 m' is not a number"},
      {"+-3", "'+-3' is not a number"},
      {"-+3", "'-+3' is not a number"},
      {"++3", "'++3' is not a number"},
      {"--3", "'--3' is not a number"},
      {"+ 3", "'+ 3' is not a number"},
      {"- 3 m", "'- 3 m' is not a number"},
      {"+", "'+' is not a number"},
      {".", "'.' is not a number"},
      {"-.", "'-.' is not a number"},
      {".e3", "'.e3' is not a number"},
      {"e3", "'e3' is not a number"},
      {"0x10", "'0x10' is not a number (hexadecimal is not accepted)"},
      {"14x20 um", "'14x20 um': unknown unit 'x'"},
      {"0X1p3 m", "hexadecimal is not accepted"},
      {"-0x1.8p1", "hexadecimal is not accepted"},
      {"inf", "value must be a finite number"},
      {"-Infinity m", "value must be a finite number"},
      {"+nan", "value must be a finite number"},
      {"NaN um", "value must be a finite number"},
  };
  for (const auto& [text, message] : refused) {
    SCOPED_TRACE(text);
    const std::string e = error_of(text);
    EXPECT_NE(e.find(message), std::string::npos) << e;
  }
}

// Overflow and underflow alike: a value that is not zero but has no double (above ~1.8e308, or
// rounding to zero below ~4.9e-324, in SI) is out of range. Subnormal values are kept.
TEST(NumberSyntax, ValuesBeyondADoubleAreOutOfRange) {
  for (const char* text :
       {"1e400", "-1e400", "1e+400 um", "1e309", "1e306 km", "1e-400", "-1e-400", "1e-400 um",
        "2e-324", "1e-316 nm", "1e-99999999999", "1e99999999999 um", "1.8e308", "0.1e-323"}) {
    SCOPED_TRACE(text);
    const std::string e = error_of(text);
    EXPECT_NE(e.find("value out of range"), std::string::npos) << e;
  }
  EXPECT_EQ(parse_quantity("4.9e-324").value, 4.9e-324);
  EXPECT_EQ(parse_quantity("1e-310").value, 1e-310);
  EXPECT_EQ(parse_quantity("1.7976931348623157e308").value, 1.7976931348623157e308);
}

// --- The fuzz-style check -------------------------------------------------------------------

// A unit, and the power of ten it is in SI.
struct PrefixedUnit {
  const char* text;
  int shift;
};
constexpr PrefixedUnit kUnits[] = {
    {"", 0},     {"m", 0},      {"um", -6},    {"\u00b5m", -6}, {"nm", -9},      {"mm", -3},
    {"cm", -2},  {"km", 3},     {"kg", 0},     {"g", -3},       {"mg", -6},      {"s", 0},
    {"ns", -9},  {"us", -6},    {"ms", -3},    {"Pa", 0},       {"kPa", 3},      {"MPa", 6},
    {"GPa", 9},  {"J/m^2", 0},  {"kJ/m^2", 3}, {"mJ/m^2", -3},  {"J/m^2/us", 6}, {"1/s", 0},
    {"1/us", 6}, {"g/cm^3", 3}, {"kg/m^3", 0}, {"um^2", -12},   {"K", 0},        {"J/kg/K", 0},
    {"km/s", 3}, {"mm/us", 3},  {"nm^-1", 9},  {"GW", 9},       {"kN", 3},
};

// A decimal written from its digits D (no point) and exponent X, value D * 10^X, in one of the
// ways people and printf write it.
struct Spelling {
  std::string text;       // "  +0012.5E+007 um"
  std::string reference;  // "-125e6": what strtod reads, the unit's shift added to X
};

Spelling spell(std::mt19937_64& rng, bool negative, const std::string& digits, int exponent,
               const PrefixedUnit& unit) {
  auto pick = [&](int n) { return static_cast<int>(rng() % static_cast<unsigned>(n)); };
  const int length = static_cast<int>(digits.size());
  const int point = pick(length + 1);  // digits before the point
  std::string mantissa = std::string(static_cast<std::size_t>(pick(3)), '0');  // leading zeros
  mantissa += digits.substr(0, static_cast<std::size_t>(point));
  const bool write_point = point < length || pick(2) == 0;
  if (write_point) mantissa += "." + digits.substr(static_cast<std::size_t>(point));
  const int written = exponent + (length - point);
  std::string text(static_cast<std::size_t>(pick(3)), ' ');
  text += negative ? "-" : pick(3) == 0 ? "+" : "";
  text += mantissa;
  if (written != 0 || pick(2) == 0) {
    text += pick(2) == 0 ? "e" : "E";
    text += written < 0 ? "-" : pick(2) == 0 ? "+" : "";
    text += std::string(static_cast<std::size_t>(pick(4)), '0') + std::to_string(std::abs(written));
  }
  // "1/s" needs its blank: "2e31/s" is 2e31 per s.
  const bool blank = pick(2) == 0 || unit.text[0] == '1';
  if (*unit.text) text += std::string(blank ? " " : "") + unit.text;
  text += std::string(static_cast<std::size_t>(pick(3)), ' ');
  const std::string reference =
      (negative ? "-" : "") + digits + "e" + std::to_string(exponent + unit.shift);
  return {text, reference};
}

// strtod (glibc's, not the from_chars the parser uses) of the reference text; nullopt outside
// the normal doubles, where strtod reports ERANGE.
std::optional<double> reference_value(const std::string& reference) {
  errno = 0;
  const double value = std::strtod(reference.c_str(), nullptr);
  if (errno == ERANGE) return std::nullopt;
  return value;
}

// The digits and exponent of a random double: its shortest round-trip form.
std::pair<std::string, int> digits_of(double value) {
  char buffer[64];
  const auto [end, ec] =
      std::to_chars(buffer, buffer + sizeof buffer, value, std::chars_format::scientific);
  const std::string text(buffer, end);  // "d.ddde[+-]XX"
  const std::size_t e = text.find('e');
  std::string digits = text.substr(0, e);
  const int fraction = digits.size() > 1 ? static_cast<int>(digits.size()) - 2 : 0;
  if (digits.size() > 1) digits.erase(1, 1);
  return {digits, std::stoi(text.substr(e + 1)) - fraction};
}

TEST(NumberSyntax, RandomSpellingsReadAsStrtodOfTheirDigits) {
  std::mt19937_64 rng(20240552);  // fixed: a failure repeats
  int checked = 0;
  for (int trial = 0; trial < 40000; ++trial) {
    std::string digits;
    int exponent = 0;
    if (trial % 2 == 0) {
      // A random double of any magnitude a case could hold, by its bits.
      std::uint64_t bits = rng();
      double value = 0.0;
      std::memcpy(&value, &bits, sizeof value);
      if (!std::isfinite(value) || value == 0.0 || std::abs(std::log10(std::abs(value))) > 290)
        continue;
      std::tie(digits, exponent) = digits_of(std::abs(value));
    } else {
      // Up to 30 random digits: long mantissas that only a correct rounding reads right.
      const int length = 1 + static_cast<int>(rng() % 30);
      for (int i = 0; i < length; ++i) digits += static_cast<char>('0' + rng() % 10);
      exponent = static_cast<int>(rng() % 561) - 280 - length;
    }
    const PrefixedUnit& unit = kUnits[rng() % std::size(kUnits)];
    const Spelling s = spell(rng, rng() % 2 == 0, digits, exponent, unit);
    const std::optional<double> expected = reference_value(s.reference);
    if (!expected) continue;
    SCOPED_TRACE("'" + s.text + "' against strtod('" + s.reference + "')");
    double value = 0.0;
    ASSERT_NO_THROW(value = parse_quantity(s.text).value);
    ASSERT_TRUE(same_double(value, *expected));
    ++checked;
  }
  EXPECT_GT(checked, 30000);
}

}  // namespace
}  // namespace coldspray::units
