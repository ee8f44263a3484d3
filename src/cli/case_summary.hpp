// A short human-readable description of a validated case, for `check` and `run`.
#pragma once

#include <iosfwd>

#include "case/case.hpp"

namespace coldspray::cli {

void print_case_summary(const case_file::Case& c, std::ostream& out);

}  // namespace coldspray::cli
