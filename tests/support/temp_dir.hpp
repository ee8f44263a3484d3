// Fresh folders for tests that write files.
#pragma once

#include <string>

namespace coldspray::testing {

// A new empty folder under the system temporary directory, named coldspray-PREFIX- and six
// characters mkdtemp chooses; removed
// with its contents when the test program exits, unless COLDSPRAY_KEEP_TEST_DIRS is set.
std::string make_temp_dir(const std::string& prefix = "test");

}  // namespace coldspray::testing
