// Command-line values that carry units ("1e7 1/s", "298 K"), read through the case-file unit
// parser so the command line and case files accept the same spellings. Unlike a case file, the
// command line takes no bare number for a length, a speed or a time: `--diameter 20` would be
// 20 m, a particle a million times too large, where the user meant 20 um.
#pragma once

#include <string>

#include "core/units.hpp"

namespace coldspray::cli {

// `text` as a quantity of `expected` dimension (units::parse_with_unit: no bare number for a
// length, a velocity or a time); InputError names `option` if malformed or of another dimension.
double parse_option_quantity(const std::string& option, const std::string& text,
                             const units::Dimension& expected);

}  // namespace coldspray::cli
