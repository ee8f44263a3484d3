// The folders of src/ as layers (docs/solvers.md): a folder includes only from the folders it may
// depend on, so that what the solvers share (bodies/, metrics/) never reaches into one solver.
// Reads every #include "folder/..." of src/ and fails on one that crosses the layers.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>

namespace {

// What each folder may include besides itself, lowest layer first.
const std::map<std::string, std::set<std::string>> kMayInclude = {
    {"core", {}},
    {"materials", {"core"}},
    {"geometry", {"core"}},
    {"case", {"core", "materials", "geometry"}},
    {"io", {"core"}},
    {"material_test", {"core", "materials"}},
    {"bonding", {"core", "case", "materials"}},
    {"bodies", {"core", "case", "materials", "geometry"}},
    {"metrics", {"core", "case", "materials", "geometry", "bodies"}},
    {"mpm", {"core", "case", "materials", "geometry", "bonding", "bodies"}},
    {"pd", {"core", "case", "materials", "geometry", "bodies"}},
    {"checkpoint", {"core", "io", "bodies", "mpm", "pd"}},
    {"run",
     {"core", "case", "materials", "io", "bodies", "bonding", "metrics", "mpm", "pd",
      "checkpoint"}},
    {"studies", {"core", "case", "io", "run"}},
    {"cli", {"core", "case", "geometry", "io", "material_test", "mpm", "pd", "run", "studies"}},
};

// The folder of a line `#include "folder/file.hpp"`, or "" for any other line. (Not std::regex:
// GCC 12 warns inside <regex> under the sanitizer build's -O2.)
std::string included_folder(const std::string& line) {
  const std::string directive = "#include \"";
  const std::size_t start = line.find_first_not_of(" \t");
  if (start == std::string::npos || line.compare(start, directive.size(), directive) != 0)
    return "";
  const std::size_t name = start + directive.size(), slash = line.find('/', name);
  if (slash == std::string::npos) return "";
  return line.substr(name, slash - name);
}

TEST(Layering, EveryIncludeStaysWithinItsLayers) {
  const std::filesystem::path src = std::filesystem::path(COLDSPRAY_SOURCE_DIR) / "src";
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(src)) {
    if (!entry.is_regular_file()) continue;
    const std::string folder = entry.path().lexically_relative(src).begin()->string();
    const auto allowed = kMayInclude.find(folder);
    ASSERT_NE(allowed, kMayInclude.end()) << "src/" << folder << " has no layer in this test";
    ++files;
    std::ifstream in(entry.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n) {
      const std::string target = included_folder(line);
      if (target.empty()) continue;
      EXPECT_TRUE(target == folder || allowed->second.count(target) != 0)
          << entry.path().lexically_relative(src).string() << ":" << n << " includes " << target
          << "/, outside the layers of src/" << folder << "/";
    }
  }
  EXPECT_GT(files, 100);
}

}  // namespace
