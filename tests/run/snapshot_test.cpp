// A peridynamics snapshot carries each point's neighbour count (`neighbours`, Int32), the
// family sizes the set-up built; an MPM snapshot, which has no families, does not. Both carry the
// plastic work per reference volume (`plastic_work`, J/m^3).
#include "run/snapshot.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "pd/setup.hpp"
#include "pd/stepper.hpp"
#include "read_text.hpp"
#include "temp_dir.hpp"

namespace coldspray::run {
namespace {

using testing::read_text;

// The values of the appended-raw array `name` (a UInt64 byte count, then the data).
template <class T>
std::vector<T> array(const std::string& vtu, const std::string& name) {
  const std::size_t tag = vtu.find("Name=\"" + name + "\"");
  if (tag == std::string::npos) return {};
  const std::size_t at = vtu.find("offset=\"", tag) + 8;
  const std::size_t offset = std::stoul(vtu.substr(at, vtu.find('"', at) - at));
  const std::size_t data = vtu.find('_', vtu.find("<AppendedData")) + 1 + offset;
  std::uint64_t bytes = 0;
  std::memcpy(&bytes, vtu.data() + data, sizeof bytes);
  std::vector<T> values(bytes / sizeof(T));
  std::memcpy(values.data(), vtu.data() + data + sizeof bytes, bytes);
  return values;
}

TEST(Snapshot, PeridynamicsWritesEachPointsNeighbourCount) {
  const std::filesystem::path folder = testing::make_temp_dir("snapshot");
  const std::string dir = folder.string();
  pd::State s = pd::build_state(case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/pd-elastic-spheres.yaml"));
  ASSERT_EQ(s.family_size.size(), s.points.size());
  write_snapshot(s, dir + "/pd.vtu");
  const std::vector<std::int32_t> written =
      array<std::int32_t>(read_text(dir + "/pd.vtu"), "neighbours");
  ASSERT_EQ(written.size(), s.points.size());
  for (std::size_t i = 0; i < written.size(); ++i)
    ASSERT_EQ(written[i], static_cast<std::int32_t>(s.families.begin[i + 1] - s.families.begin[i]));

  s.family_size.clear();  // as in an MPM run
  write_snapshot(s, dir + "/mpm.vtu");
  const std::string mpm = read_text(dir + "/mpm.vtu");
  EXPECT_EQ(mpm.find("neighbours"), std::string::npos);
  EXPECT_NE(mpm.find("Name=\"plastic_work\""), std::string::npos);
}

// 40 steps of the coarse quarter Cu impact at 500 m/s: the snapshot's plastic_work is each
// point's accumulated plastic work over its reference volume, and some points have done some.
TEST(Snapshot, WritesThePlasticWorkPerReferenceVolume) {
  const std::filesystem::path folder = testing::make_temp_dir("snapshot");
  const case_file::Case c = case_file::load_case(
      std::string(COLDSPRAY_SOURCE_DIR) + "/examples/verification/pd-quarter-impact.yaml",
      {{"symmetry.x", "0 um"}, {"symmetry.y", "0 um"}});
  pd::State s = pd::build_state(c);
  for (int n = 0; n < 40; ++n) {
    s.dt = pd::stable_time_step(s, c.solver.cfl);
    pd::step(s);
  }
  const bodies::Points& P = s.points;
  write_snapshot(s, (folder / "pd.vtu").string());
  const std::vector<double> written =
      array<double>(read_text((folder / "pd.vtu").string()), "plastic_work");
  ASSERT_EQ(written.size(), P.size());
  double plastic = 0.0;
  for (std::size_t p = 0; p < P.size(); ++p) {
    EXPECT_DOUBLE_EQ(written[p], P.plastic_work[p] / P.volume0[p]) << "point " << p;
    plastic += P.plastic_work[p];
  }
  EXPECT_GT(plastic, 0.0);
}

}  // namespace
}  // namespace coldspray::run
