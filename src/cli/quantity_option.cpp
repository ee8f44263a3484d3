#include "cli/quantity_option.hpp"

#include <array>

#include "core/error.hpp"

namespace coldspray::cli {

namespace {

// The dimensions whose bare numbers are refused, with the unit a message suggests.
struct NeedsUnit {
  units::Dimension dimension;
  const char* example;
};
constexpr std::array<NeedsUnit, 3> kNeedUnits{
    {{units::kLength, "um"}, {units::kVelocity, "m/s"}, {units::kTime, "ns"}}};

}  // namespace

double parse_with_unit(const std::string& text, const units::Dimension& expected) {
  const double value = units::parse_as(text, expected);
  if (units::parse_quantity(text).dimension == expected) return value;
  for (const NeedsUnit& n : kNeedUnits)
    if (n.dimension == expected)
      throw UnitError("'" + text + "' has no unit: give the " + units::dimension_name(expected) +
                      " with its unit, e.g. '" + text + n.example + "'");
  return value;
}

double parse_option_quantity(const std::string& option, const std::string& text,
                             const units::Dimension& expected) {
  try {
    return parse_with_unit(text, expected);
  } catch (const UnitError& e) {
    throw InputError(option, "", e.what());
  }
}

}  // namespace coldspray::cli
