// Physical dimensions and the parsing of quantities written with units ("14 um", "1.5 GPa").
// Everything inside coldspray is SI; this is the one place where other units are converted.
#pragma once

#include <string>
#include <string_view>

namespace coldspray::units {

// Exponents of the SI base dimensions a quantity carries: kg^mass m^length s^time K^temperature.
struct Dimension {
  int mass = 0;
  int length = 0;
  int time = 0;
  int temperature = 0;

  friend constexpr bool operator==(const Dimension&, const Dimension&) = default;
  constexpr Dimension operator*(const Dimension& o) const {
    return {mass + o.mass, length + o.length, time + o.time, temperature + o.temperature};
  }
  constexpr Dimension operator/(const Dimension& o) const {
    return {mass - o.mass, length - o.length, time - o.time, temperature - o.temperature};
  }
  constexpr Dimension pow(int k) const { return {mass * k, length * k, time * k, temperature * k}; }
};

inline constexpr Dimension kDimensionless{};
inline constexpr Dimension kMass{1, 0, 0, 0};
inline constexpr Dimension kLength{0, 1, 0, 0};
inline constexpr Dimension kTime{0, 0, 1, 0};
inline constexpr Dimension kTemperature{0, 0, 0, 1};
inline constexpr Dimension kVelocity = kLength / kTime;
inline constexpr Dimension kRate = kDimensionless / kTime;  // strain rate, 1/s
inline constexpr Dimension kForce = kMass * kLength / kTime.pow(2);
inline constexpr Dimension kEnergy = kForce * kLength;
inline constexpr Dimension kPressure = kForce / kLength.pow(2);  // also stress, energy density
inline constexpr Dimension kDensity = kMass / kLength.pow(3);
inline constexpr Dimension kEnergyPerArea = kEnergy / kLength.pow(2);
inline constexpr Dimension kEnergyPerAreaPerTime = kEnergyPerArea / kTime;
inline constexpr Dimension kSpecificHeat = kEnergy / kMass / kTemperature;
inline constexpr Dimension kThermalConductivity = kEnergy / kTime / kLength / kTemperature;

struct Quantity {
  double value = 0.0;  // in SI
  Dimension dimension;
};

// Parses "VALUE" or "VALUE UNIT", where VALUE is a decimal number ("810", "+1.5E-03", ".5",
// "1e+12"; no hexadecimal, inf or nan) and UNIT is a product of known units with optional
// integer powers, separated by '*' or '/', e.g. "J/m^2/us", "kg/m^3", "1/s", "m/s". A value
// whose SI value overflows a double, or is not zero and rounds to zero, is out of range.
// A bare number is taken as SI and reported as dimensionless (the caller decides whether a bare
// number is acceptable for the expected dimension). Throws UnitError on malformed text.
Quantity parse_quantity(std::string_view text);

// Parses text and checks it has `expected` dimension; a bare number is accepted as SI of that
// dimension. Throws UnitError naming both dimensions on a mismatch.
double parse_as(std::string_view text, const Dimension& expected);

// As parse_as, but a bare number where a length, a velocity or a time is expected is a UnitError
// that suggests a unit: where a user types a quantity (the command line, a grid's CELL/SPACING)
// rather than a case file's value, `20` for a diameter would be 20 m where 20 um was meant.
double parse_with_unit(const std::string& text, const Dimension& expected);

// Human-readable SI unit for a dimension, e.g. "Pa", "m/s", "kg/m^3", "J/m^2/s", "1/s", "-".
std::string si_unit(const Dimension& d);

// A short physical name for messages, e.g. "length", "velocity", "pressure"; falls back to si_unit.
std::string dimension_name(const Dimension& d);

}  // namespace coldspray::units
