// The folders of src/ as layers (docs/solvers.md): a folder includes only from the folders it may
// depend on, so that what the solvers share (bodies/, metrics/) never reaches into one solver.
// Reads every #include "folder/..." of src/ and fails on one that crosses the layers; and every
// one of bench/ and tests/, which may not include cli/; and follows the headers the solvers
// include, which may not reach yaml-cpp.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

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
    {"mpm", {"core", "case", "materials", "geometry", "bonding", "bodies", "metrics"}},
    {"pd", {"core", "case", "materials", "geometry", "bodies", "metrics"}},
    {"checkpoint", {"core", "io", "bodies", "mpm", "pd"}},
    {"run",
     {"core", "case", "materials", "io", "bodies", "bonding", "metrics", "mpm", "pd",
      "checkpoint"}},
    {"studies", {"core", "case", "io", "run"}},
    // The case builders and study-file schemas, below the command line so that the benchmarks
    // and any other front end build an impact without it.
    {"setups", {"core", "case", "geometry", "studies"}},
    {"cli", {"core", "case", "geometry", "io", "material_test", "pd", "run", "studies", "setups"}},
};

// The path of a line `#include "path"` (open '"') or `#include <path>` (open '<'), or "" for any
// other line. (Not std::regex: GCC 12 warns inside <regex> under the sanitizer build's -O2.)
std::string included_path(const std::string& line, char open) {
  const std::string directive = std::string("#include ") + open;
  const std::size_t start = line.find_first_not_of(" \t");
  if (start == std::string::npos || line.compare(start, directive.size(), directive) != 0)
    return "";
  const std::size_t name = start + directive.size();
  const std::size_t close = line.find(open == '<' ? '>' : '"', name);
  return close == std::string::npos ? "" : line.substr(name, close - name);
}

// The folder of a line `#include "folder/file.hpp"`, or "" for any other line.
std::string included_folder(const std::string& line) {
  const std::string path = included_path(line, '"');
  const std::size_t slash = path.find('/');
  return slash == std::string::npos ? "" : path.substr(0, slash);
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

// Each solver answers its own questions (docs/solvers.md, "The seam"): solver.method is read where
// a case is parsed (case/), chosen (cli/impact_options.cpp) or written (setups/), dispatched once
// in run/solver.hpp, and answered in mpm/ and pd/. Elsewhere no code tests the method or which
// state a SolverState holds.
TEST(Layering, OnlyTheSeamTestsTheSolverMethod) {
  const std::filesystem::path src = std::filesystem::path(COLDSPRAY_SOURCE_DIR) / "src";
  const std::set<std::string> may_test = {"case", "setups", "mpm", "pd"};
  const std::set<std::string> files_that_may = {"cli/impact_options.cpp", "run/solver.hpp",
                                                "run/solver.cpp"};
  const std::vector<std::string> tests = {
      "Method::Mpm",  "Method::Peridynamics", "holds_alternative<mpm::", "holds_alternative<pd::",
      "get_if<mpm::", "get_if<pd::"};
  int files = 0;
  for (const auto& entry : std::filesystem::recursive_directory_iterator(src)) {
    if (!entry.is_regular_file()) continue;
    const std::string file = entry.path().lexically_relative(src).generic_string();
    if (may_test.count(file.substr(0, file.find('/'))) != 0 || files_that_may.count(file) != 0)
      continue;
    ++files;
    std::ifstream in(entry.path());
    std::string line;
    for (int n = 1; std::getline(in, line); ++n)
      for (const std::string& t : tests)
        EXPECT_EQ(line.find(t), std::string::npos)
            << "src/" << file << ":" << n << " tests the solver (" << t
            << "): answer it in mpm/answers.hpp and pd/answers.hpp, through run::with_solver";
  }
  EXPECT_GT(files, 100);
}

// The command line is the top layer: the benchmarks and the tests build their cases through
// setups/, and include nothing of cli/.
TEST(Layering, BenchmarksAndTestsIncludeNoCommandLineCode) {
  int files = 0;
  for (const char* folder : {"bench", "tests"}) {
    const std::filesystem::path root = std::filesystem::path(COLDSPRAY_SOURCE_DIR) / folder;
    for (const auto& entry : std::filesystem::recursive_directory_iterator(root)) {
      if (!entry.is_regular_file()) continue;
      ++files;
      std::ifstream in(entry.path());
      std::string line;
      for (int n = 1; std::getline(in, line); ++n)
        EXPECT_NE(included_folder(line), "cli")
            << folder << "/" << entry.path().lexically_relative(root).string() << ":" << n
            << " includes cli/: build cases through setups/";
    }
  }
  EXPECT_GT(files, 50);
}

// The solvers and what they stand on read a parsed Case, never its YAML: no file of these folders
// reaches <yaml-cpp/...> through the headers of src/ it includes, directly or through others.
TEST(Layering, SolverCodeReachesNoYaml) {
  const std::filesystem::path src = std::filesystem::path(COLDSPRAY_SOURCE_DIR) / "src";
  int files = 0;
  for (const char* folder : {"mpm", "pd", "bodies", "geometry"}) {
    for (const auto& entry : std::filesystem::recursive_directory_iterator(src / folder)) {
      if (!entry.is_regular_file()) continue;
      ++files;
      // The files still to read, each with the chain of includes that reached it.
      std::vector<std::pair<std::filesystem::path, std::string>> pending{
          {entry.path(), entry.path().lexically_relative(src).string()}};
      std::set<std::filesystem::path> seen;
      while (!pending.empty()) {
        const auto [file, chain] = pending.back();
        pending.pop_back();
        std::ifstream in(file);
        std::string line;
        while (std::getline(in, line)) {
          if (included_path(line, '<').rfind("yaml-cpp/", 0) == 0)
            ADD_FAILURE() << chain << " includes <" << included_path(line, '<') << ">";
          const std::string header = included_path(line, '"');
          if (header.empty() || !std::filesystem::is_regular_file(src / header)) continue;
          if (seen.insert(src / header).second)
            pending.emplace_back(src / header, chain + " -> " + header);
        }
      }
    }
  }
  EXPECT_GT(files, 50);
}

}  // namespace
