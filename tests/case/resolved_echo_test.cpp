#include <gtest/gtest.h>

#include <fstream>
#include <sstream>

#include "case/load.hpp"
#include "case_test_support.hpp"

namespace coldspray::case_file {
namespace {

using testing::case_path;

std::string resolved_text(const Case& c) {
  std::ostringstream out;
  write_resolved(c, out);
  return out.str();
}

// Writes the resolved echo of `c` and reads it back.
Case round_trip(const Case& c, const std::string& file) {
  const std::string path = ::testing::TempDir() + file;
  std::ofstream(path) << resolved_text(c);
  return load_case(path);
}

void expect_same_case(const Case& a, const Case& b) {
  EXPECT_EQ(a.name, b.name);
  EXPECT_EQ(a.description, b.description);
  EXPECT_EQ(a.bodies, b.bodies);
  EXPECT_EQ(a.grid, b.grid);
  EXPECT_EQ(a.solver, b.solver);
  EXPECT_EQ(a.contact, b.contact);
  EXPECT_EQ(a.output, b.output);
  ASSERT_EQ(a.materials.size(), b.materials.size());
  for (const auto& [name, material] : a.materials) {
    ASSERT_TRUE(b.materials.contains(name)) << name;
    testing::expect_same(material, b.materials.at(name));
  }
}

TEST(ResolvedEcho, ReadsBackToTheSameCase) {
  const Case original = load_case(case_path("full.yaml"));
  expect_same_case(original, round_trip(original, "full.resolved.yaml"));
}

TEST(ResolvedEcho, ReadsBackDefaultsAndOverridesExactly) {
  // Numbers whose SI values have no short decimal form must survive the echo bit for bit.
  const Case original = load_case(
      case_path("minimal.yaml"),
      {parse_override("bodies.particle.spacing=0.123456789012345678 um"),
       parse_override("solver.end_time=76.54321098765432 ns"), parse_override("solver.cfl=0.1"),
       parse_override("materials.m={base: cu-ptw, elastic: {youngs_modulus: 117 GPa, "
                      "poisson_ratio: 0.34}}"),
       parse_override("bodies.particle.material=m"), parse_override("solver.dt_scale=0.7")});
  const Case back = round_trip(original, "minimal.resolved.yaml");
  expect_same_case(original, back);
  EXPECT_EQ(back.bodies[0].spacing, 0.123456789012345678e-6);
}

TEST(ResolvedEcho, IsStableWhenWrittenAgain) {
  Case original = load_case(case_path("full.yaml"));
  Case back = round_trip(original, "stable.resolved.yaml");
  original.source_file.clear();
  back.source_file.clear();
  EXPECT_EQ(resolved_text(original), resolved_text(back));
}

TEST(ResolvedEcho, WritesEveryDefaultInSi) {
  const std::string text = resolved_text(load_case(case_path("minimal.yaml")));
  for (const char* part :
       {"cfl: 0.3", "method: mpm", "geometry: 3d", "shape_function: gimp", "enabled: true",
        "linear: 0.06", "quadratic: 1.5", "normal: max-gradient", "friction: 0",
        "history_interval: 0  # s", "probes: []", "zmax: free", "temperature: 298  # K",
        "velocity: [0, 0, 0]  # m/s", "spacing: 1.75e-07  # m", "taylor_quinney: 0.9",
        "mu0: 2.88e+10  # Pa", "model: ptw", "absorbing: []"}) {
    EXPECT_TRUE(testing::contains(text, part));
  }
  EXPECT_FALSE(testing::contains(text, "dt_scale"));  // unset optional values are left out
  EXPECT_FALSE(testing::contains(text, "base:"));     // materials are written out in full
}

}  // namespace
}  // namespace coldspray::case_file
