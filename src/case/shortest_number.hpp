// Numbers as text for people and for the resolved echo: the fewest significant digits that read
// back to the same double ("2.6e+10", "1.75e-07", "2700").
#pragma once

#include <string>

namespace coldspray::case_file {

std::string shortest_text(double value);

}  // namespace coldspray::case_file
