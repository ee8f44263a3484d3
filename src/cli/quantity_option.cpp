#include "cli/quantity_option.hpp"

#include "core/error.hpp"

namespace coldspray::cli {

double parse_option_quantity(const std::string& option, const std::string& text,
                             const units::Dimension& expected) {
  try {
    return units::parse_with_unit(text, expected);
  } catch (const UnitError& e) {
    throw InputError(option, "", e.what());
  }
}

}  // namespace coldspray::cli
