// A peridynamics snapshot carries each point's neighbour count (`neighbours`, Int32), the
// family sizes the set-up built; an MPM snapshot, which has no families, does not.
#include "run/snapshot.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "pd/setup.hpp"

namespace coldspray::run {
namespace {

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// The Int32 values of the appended-raw array `name` (a UInt64 byte count, then the data).
std::vector<std::int32_t> int_array(const std::string& vtu, const std::string& name) {
  const std::size_t tag = vtu.find("Name=\"" + name + "\"");
  if (tag == std::string::npos) return {};
  const std::size_t at = vtu.find("offset=\"", tag) + 8;
  const std::size_t offset = std::stoul(vtu.substr(at, vtu.find('"', at) - at));
  const std::size_t data = vtu.find('_', vtu.find("<AppendedData")) + 1 + offset;
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, vtu.data() + data, sizeof bytes);
  std::vector<std::int32_t> values(bytes / sizeof(std::int32_t));
  std::memcpy(values.data(), vtu.data() + data + sizeof bytes, bytes);
  return values;
}

TEST(Snapshot, PeridynamicsWritesEachPointsNeighbourCount) {
  const std::filesystem::path folder =
      std::filesystem::temp_directory_path() /
      ("coldspray_snapshot_" + std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
  std::filesystem::create_directories(folder);
  const std::string dir = folder.string();
  pd::State s = pd::build_state(case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/pd-elastic-spheres.yaml"));
  ASSERT_EQ(s.family_size.size(), s.points.size());
  write_snapshot(s, dir + "/pd.vtu");
  const std::vector<std::int32_t> written = int_array(read_file(dir + "/pd.vtu"), "neighbours");
  ASSERT_EQ(written.size(), s.points.size());
  for (std::size_t i = 0; i < written.size(); ++i)
    ASSERT_EQ(written[i], static_cast<std::int32_t>(s.families.begin[i + 1] - s.families.begin[i]));

  s.family_size.clear();  // as in an MPM run
  write_snapshot(s, dir + "/mpm.vtu");
  EXPECT_EQ(read_file(dir + "/mpm.vtu").find("neighbours"), std::string::npos);
  std::filesystem::remove_all(folder);
}

}  // namespace
}  // namespace coldspray::run
