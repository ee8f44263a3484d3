// Command-line values that carry units ("1e7 1/s", "298 K"), read through the case-file unit
// parser so the command line and case files accept the same spellings.
#pragma once

#include <string>

#include "core/units.hpp"

namespace coldspray::cli {

// Parses `text` as a quantity of `expected` dimension; InputError names `option` on failure.
double parse_option_quantity(const std::string& option, const std::string& text,
                             const units::Dimension& expected);

}  // namespace coldspray::cli
