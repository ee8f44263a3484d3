// The command line's guards against input that crashed or stalled it (docs/reliability.md,
// "Input that cannot crash or stall"): each refusal exits with status 2, names the option or the
// FILE:LINE:COLUMN and key, and writes nothing.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "run_command.hpp"
#include "source_paths.hpp"
#include "temp_dir.hpp"

namespace coldspray::testing {
namespace {

namespace fs = std::filesystem;

// It died with SIGSEGV (status 139): the document walk recursed through the self-reference.
TEST(InputGuards, CheckRefusesASelfReferenceInSet) {
  const auto r = run_coldspray("check '" + kExample + "' --set 'solver.cfl=&a [*a]'");
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r,
                  "error: --set solver.cfl: key 'solver.cfl': YAML anchors (&NAME) are not "
                  "accepted"))
      << r.output;
}

// It segfaulted: every thread reserved its stack and buffers.
TEST(InputGuards, ThreadsBeyondTheMachineAreRefused) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray("run '" + kExample + "' --threads 100000 --out result", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r, "--threads: '100000': give a whole number from 1 to")) << r.output;
  EXPECT_TRUE(has(r, "the processors of this machine")) << r.output;
  EXPECT_TRUE(fs::is_empty(dir));
}

// It ran 0 cases and exited 0: the count of values overflowed a long.
TEST(InputGuards, ASweepRangeOfAbsurdlyManyValuesIsRefused) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray(
      "sweep '" + kExample + "' --vary 'solver.cfl=0.1:1:1e-20' --out sw --quiet", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r, "--vary solver.cfl=0.1:1:1e-20: 9e+19 values: at most 100000")) << r.output;
  EXPECT_TRUE(fs::is_empty(dir));
  const auto product = run_coldspray("sweep '" + kExample +
                                         "' --vary 'solver.cfl=0.1:0.2:0.0001' --vary "
                                         "'contact.mpm.friction=0:1:0.001' --out sw --quiet",
                                     dir);
  EXPECT_EQ(product.status, 2) << product.output;
  EXPECT_TRUE(has(product, "combinations of the varied values: at most 100000")) << product.output;
  EXPECT_TRUE(fs::is_empty(dir));
}

// `radius: 7 mm` in a micrometre case: check said OK; run died of std::bad_alloc (status 1).
TEST(InputGuards, CheckAndRunRefuseAPointCountBeyondTheMemory) {
  const std::string dir = make_temp_dir();
  for (const char* command : {"check", "run --out result"}) {
    const auto r = run_coldspray(
        std::string(command) + " '" + kExample + "' --set 'bodies.particle.shape.radius=7 mm'",
        dir);
    EXPECT_EQ(r.status, 2) << r.output;
    EXPECT_TRUE(has(r,
                    "error: --set bodies.particle.shape.radius: key "
                    "'bodies.particle.shape.radius': the bodies would have about"))
        << r.output;
    EXPECT_TRUE(has(r, "limits.max_points, by default")) << r.output;
  }
  EXPECT_TRUE(fs::is_empty(dir));
}

// An overlap found at set-up named the file only.
TEST(InputGuards, SetUpErrorsNameFileLineAndColumn) {
  const std::string dir = make_temp_dir();
  const auto r = run_coldspray("run '" + kData + "/cli/overlap.yaml' --out result", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r, "overlap.yaml:5:5: key 'bodies.particle.shape': body 'particle' overlaps"))
      << r.output;
  EXPECT_TRUE(fs::is_empty(dir));
}

// It failed in the first step with exit 3 ("more than 8 bodies meet at grid node"): bodies that
// start with more at a node than the contact holds are bad input.
TEST(InputGuards, NineBodiesAtOneNodeAreRefusedBeforeTheRun) {
  const std::string dir = make_temp_dir();
  const auto r =
      run_coldspray("run '" + kData + "/cli/nine-bodies-at-a-node.yaml' --out result", dir);
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_TRUE(has(r,
                  "nine-bodies-at-a-node.yaml:4:1: key 'bodies': 9 bodies reach the grid node "
                  "at (0, 0, 0) um at t = 0; the contact holds at most 8 bodies at a node"))
      << r.output;
  EXPECT_TRUE(fs::is_empty(dir));
}

}  // namespace
}  // namespace coldspray::testing
