// The interface a pull-off test reads (metrics/interface_areas.hpp) of the impacted state a
// checkpoint holds.
#pragma once

#include <filesystem>

#include "case/case.hpp"
#include "metrics/interface_areas.hpp"

namespace coldspray::run {

// Of body `body` of case `c` in the state checkpoint `file` (of that case) holds, for the whole
// body (symmetry planes counted).
metrics::InterfaceAreas interface_areas(const case_file::Case& c, const std::filesystem::path& file,
                                        std::size_t body);

}  // namespace coldspray::run
