// Fresh folders for tests that write files.
#pragma once

#include <string>

namespace coldspray::testing {

// A new empty folder under the system temporary directory, named coldspray-PREFIX-XXXXXX.
std::string make_temp_dir(const std::string& prefix = "test");

}  // namespace coldspray::testing
