// Output paths (docs/reliability.md, "Output folders"): an --out that cannot hold results is bad
// input (exit 2) with the reason; atomic writes replace only regular files; a folder that holds a
// previous run's results is refused without --overwrite and cleared of them with it.
#include <gtest/gtest.h>
#include <sys/stat.h>

#include <filesystem>
#include <fstream>
#include <set>
#include <string>

#include "read_text.hpp"
#include "run_command.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

namespace fs = std::filesystem;

// A run of a fraction of a nanosecond.
const std::string kShortRun = "run '" + std::string(COLDSPRAY_SOURCE_DIR) +
                              "/examples/verification/elastic-wave.yaml' --quiet --threads 1 "
                              "--set solver.end_time=0.3ns";
const std::string kMaterialTest =
    "material-test --material al-ptw --strain-rate 1e3 --final-strain -0.1 --steps 20";

TEST(OutputPaths, AnOutThatIsAFileIsBadInput) {
  const std::string dir = make_temp_dir("out");
  std::ofstream(fs::path(dir) / "taken") << "mine\n";
  const auto r = run_coldspray(kShortRun + " --out taken", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("output folder 'taken': it is a file, not a folder"), std::string::npos)
      << r.output;
  EXPECT_EQ(read_text(fs::path(dir) / "taken"), "mine\n");
}

TEST(OutputPaths, AnOutUnderAFileIsBadInput) {
  const std::string dir = make_temp_dir("out");
  std::ofstream(fs::path(dir) / "taken") << "mine\n";
  const auto r = run_coldspray(kShortRun + " --out taken/result", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("is a file, not a folder"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("taken'"), std::string::npos) << r.output;
}

TEST(OutputPaths, ASweepOutThatIsAFileIsBadInput) {
  const std::string dir = make_temp_dir("out");
  std::ofstream(fs::path(dir) / "taken") << "mine\n";
  const auto r =
      run_coldspray("sweep '" + std::string(COLDSPRAY_TEST_DATA) +
                        "/cli/escape.yaml' --out taken --quiet --vary 'solver.cfl=0.3,0.4'",
                    dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("output folder 'taken': it is a file, not a folder"), std::string::npos)
      << r.output;
  EXPECT_EQ(read_text(fs::path(dir) / "taken"), "mine\n");
}

// /proc takes no new folders and no files, even from root.
TEST(OutputPaths, AnOutThatCannotBeCreatedIsBadInput) {
  const auto r = run_coldspray(kShortRun + " --out /proc/coldspray-results");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("output folder '/proc/coldspray-results': cannot create it"),
            std::string::npos)
      << r.output;
}

TEST(OutputPaths, AnOutThatCannotBeWrittenInIsBadInput) {
  const auto r = run_coldspray(kShortRun + " --out /proc");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("output folder '/proc': cannot write in it"), std::string::npos)
      << r.output;
}

// The rename of an atomic write would put a regular file in place of the link, not of its target.
TEST(OutputPaths, MaterialTestDoesNotReplaceASymbolicLink) {
  const std::string dir = make_temp_dir("out");
  const fs::path target = fs::path(dir) / "target.txt", link = fs::path(dir) / "link.csv";
  std::ofstream(target) << "keep\n";
  fs::create_symlink(target, link);
  const auto r = run_coldspray(kMaterialTest + " --out link.csv", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--out: 'link.csv' is a symbolic link; only a regular file is replaced"),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read_text(target), "keep\n");
}

TEST(OutputPaths, MaterialTestDoesNotReplaceAFifo) {
  const std::string dir = make_temp_dir("out");
  const fs::path fifo = fs::path(dir) / "fifo.csv";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  const auto r = run_coldspray(kMaterialTest + " --out fifo.csv", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("'fifo.csv' is a fifo"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_fifo(fifo));
}

TEST(OutputPaths, MaterialTestStillReplacesARegularFile) {
  const std::string dir = make_temp_dir("out");
  std::ofstream(fs::path(dir) / "old.csv") << "old\n";
  const auto r = run_coldspray(kMaterialTest + " --out old.csv", dir);
  EXPECT_EQ(r.status, 0) << r.output;
  EXPECT_EQ(read_text(fs::path(dir) / "old.csv").rfind("time,strain", 0), 0u);
}

TEST(OutputPaths, ImpactWriteCaseDoesNotReplaceASymbolicLink) {
  const std::string dir = make_temp_dir("out");
  const fs::path target = fs::path(dir) / "target.txt", link = fs::path(dir) / "case.yaml";
  std::ofstream(target) << "keep\n";
  fs::create_symlink(target, link);
  const auto r = run_coldspray(
      "impact --material al-ptw --diameter 10um --velocity 600m/s --write-case case.yaml", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find("--write-case: 'case.yaml' is a symbolic link"), std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::is_symlink(link));
  EXPECT_EQ(read_text(target), "keep\n");
}

// The snapshots in DIR/snapshots and those DIR/snapshots.pvd lists.
std::set<std::string> snapshot_files(const fs::path& out) {
  std::set<std::string> files;
  for (const auto& entry : fs::directory_iterator(out / "snapshots"))
    files.insert("snapshots/" + entry.path().filename().string());
  return files;
}
std::set<std::string> listed_snapshots(const fs::path& out) {
  const std::string pvd = read_text(out / "snapshots.pvd");
  // (Not std::regex: GCC 12 warns inside <regex> under the sanitizer build's -O2.)
  const std::string key = "file=\"";
  std::set<std::string> listed;
  for (std::size_t at = pvd.find(key); at != std::string::npos; at = pvd.find(key, at)) {
    at += key.size();
    listed.insert(pvd.substr(at, pvd.find('"', at) - at));
  }
  return listed;
}

// A first run with a snapshot every 0.05 ns, a second with the first and last only: the second is
// refused, then with --overwrite leaves only its own snapshots (once, the first run's stayed
// beside a .pvd that did not list them), and a file of the user's in the folder stays.
TEST(OutputPaths, AReusedOutFolderIsRefusedWithoutOverwriteAndClearedWithIt) {
  const std::string dir = make_temp_dir("out");
  const fs::path out = fs::path(dir) / "result";
  const auto first =
      run_coldspray(kShortRun + " --out result --set output.snapshot_interval=0.05ns", dir);
  ASSERT_EQ(first.status, 0) << first.output;
  ASSERT_GT(snapshot_files(out).size(), 2u);
  std::ofstream(out / "notes.txt") << "mine\n";

  const auto refused = run_coldspray(kShortRun + " --out result", dir);
  EXPECT_EQ(refused.status, 2) << refused.output;
  EXPECT_NE(refused.output.find("holds a previous run's results"), std::string::npos)
      << refused.output;
  EXPECT_NE(refused.output.find("--overwrite"), std::string::npos) << refused.output;

  const auto second = run_coldspray(kShortRun + " --out result --overwrite", dir);
  ASSERT_EQ(second.status, 0) << second.output;
  EXPECT_EQ(snapshot_files(out).size(), 2u);
  EXPECT_EQ(snapshot_files(out), listed_snapshots(out));
  EXPECT_EQ(read_text(out / "notes.txt"), "mine\n");
}

}  // namespace
}  // namespace coldspray::testing
