// Where the repository's examples and test data are, for the tests that run coldspray on them
// (COLDSPRAY_SOURCE_DIR and COLDSPRAY_TEST_DATA come from tests/CMakeLists.txt).
#pragma once

#include <string>

namespace coldspray::testing {

inline const std::string kData = COLDSPRAY_TEST_DATA;  // tests/data
inline const std::string kExamples = std::string(COLDSPRAY_SOURCE_DIR) + "/examples";
inline const std::string kExample = kExamples + "/al-14um-810.yaml";  // the default case

}  // namespace coldspray::testing
