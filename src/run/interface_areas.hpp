// The areas a pull-off test divides its peak force by (docs/pull-off.md), measured on the state a
// checkpoint holds.
#pragma once

#include <filesystem>

#include "case/case.hpp"

namespace coldspray::run {

struct InterfaceAreas {
  double bonded = 0.0;     // the surface area of the body's points another body acts on, m^2
  double projected = 0.0;  // pi d^2 / 4, d the footprint's diameter (the flattening ratio's), m^2
};

// Of body `body` of case `c` in the state checkpoint `file` (of that case) holds, for the whole
// body (symmetry planes counted).
InterfaceAreas interface_areas(const case_file::Case& c, const std::filesystem::path& file,
                               std::size_t body);

}  // namespace coldspray::run
