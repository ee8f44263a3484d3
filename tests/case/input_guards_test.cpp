// Input that cannot crash or stall (docs/reliability.md): YAML aliases and deep nesting refused,
// unknown keys found in time linear in the keys, and the size caps checked at load, before
// anything is allocated. Each refusal is an InputError naming FILE:LINE:COLUMN (or --set KEY)
// and the key.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "case/load.hpp"
#include "case_test_support.hpp"
#include "run/solver.hpp"

namespace coldspray::case_file {
namespace {

using testing::case_path;
using testing::contains;
using testing::input_error;

const std::string kCase = R"(name: guarded
bodies:
  - name: particle
    material: al-ptw
    shape: {type: sphere, center: [0, 0, 7 um], radius: 7 um}
    spacing: 0.7 um
    velocity: [0, 0, -500 m/s]
  - name: substrate
    material: al-ptw
    shape: {type: cylinder, base_center: [0, 0, -10 um], radius: 15 um, height: 10 um}
    spacing: 0.7 um
grid:
  cell_size: 1.4 um
solver:
  end_time: 20 ns
)";

// kCase with `from` replaced by `to`.
std::string edited(const std::string& from, const std::string& to) {
  std::string text = kCase;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << from;
  return text.replace(at, from.size(), to);
}

InputError error_of(const std::string& text, const std::vector<Override>& overrides = {}) {
  return input_error([&] { load_case_text("guarded.yaml", text, {}, overrides); });
}

TEST(InputGuards, TheGuardedCaseLoads) { EXPECT_NO_THROW(load_case_text("guarded.yaml", kCase)); }

// `--set 'solver.cfl=&a [*a]'` made a list that contains itself: the walk of the document
// overflowed the stack (SIGSEGV).
TEST(InputGuards, ASelfReferenceInSetIsRefused) {
  const InputError e = error_of(kCase, {parse_override("solver.cfl=&a [*a]")});
  EXPECT_EQ(e.where(), "--set solver.cfl");
  EXPECT_EQ(e.key(), "solver.cfl");
  EXPECT_TRUE(contains(e.message(), "YAML anchors (&NAME) are not accepted"));
}

// Seven levels of nine aliases each in 283 characters stood for 9^7 nodes: 19 s to refuse.
TEST(InputGuards, NestedAliasesInSetAreRefusedAtOnce) {
  std::string value = "[&a0 [1,1,1,1,1,1,1,1,1]";
  for (int i = 1; i < 7; ++i) {
    value += ", &a" + std::to_string(i) + " [";
    for (int j = 0; j < 9; ++j) value += (j ? ",*a" : "*a") + std::to_string(i - 1);
    value += "]";
  }
  value += "]";
  const auto start = std::chrono::steady_clock::now();
  const InputError e = error_of(kCase, {parse_override("solver.cfl=" + value)});
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 1.0);
  EXPECT_EQ(e.where(), "--set solver.cfl");
  EXPECT_TRUE(contains(e.message(), "not accepted"));
}

TEST(InputGuards, AnAliasInAFileIsRefusedAtItsLine) {
  const InputError e =
      error_of(edited("    spacing: 0.7 um\n    velocity", "    spacing: &s 0.7 um\n    velocity") +
               "output: {history_interval: *s}\n");
  EXPECT_EQ(e.where(), "guarded.yaml:6:14");
  EXPECT_EQ(e.key(), "");
  EXPECT_TRUE(contains(e.message(), "YAML anchors (&NAME) are not accepted"));
  // An alias without its anchor is the parser's error, at the alias.
  const InputError alias = error_of(kCase + "output: {history_interval: *s}\n");
  EXPECT_EQ(alias.where(), "guarded.yaml:16:28");
}

TEST(InputGuards, DeepNestingIsRefused) {
  const std::string deep = std::string(100, '[') + "1" + std::string(100, ']');
  const InputError e = error_of(kCase, {parse_override("solver.cfl=" + deep)});
  EXPECT_EQ(e.where(), "--set solver.cfl");
  EXPECT_TRUE(contains(e.message(), "nested more than 32 deep"));
  std::string path = "solver";
  for (int i = 0; i < 40; ++i) path += ".x";
  const InputError long_path = error_of(kCase, {parse_override(path + "=1")});
  EXPECT_TRUE(contains(long_path.message(), "a key path of more than 32 names"));
}

// 100k unknown top-level keys took 48 s to report the first: duplicates were looked for by
// comparing every key with every earlier one.
TEST(InputGuards, ManyKeysAreReadInLinearTime) {
  std::string text = kCase;
  for (int i = 0; i < 100000; ++i) text += "unknown_key_" + std::to_string(i) + ": 1\n";
  const auto start = std::chrono::steady_clock::now();
  const InputError e = error_of(text);
  EXPECT_LT(std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(), 10.0);
  EXPECT_EQ(e.where(), "guarded.yaml:16:1");
  EXPECT_EQ(e.key(), "unknown_key_0");
  const InputError duplicate =
      error_of(text.replace(text.find("unknown_key_99999"), 17, "unknown_key_1"));
  EXPECT_TRUE(contains(duplicate.message(), "duplicate key 'unknown_key_1'"));
}

// `radius: 7 mm` in a micrometre case passed check with ~5e15 points; run died of bad_alloc.
TEST(InputGuards, APointCountBeyondTheMemoryIsRefusedAtTheShape) {
  const InputError e = error_of(edited("radius: 7 um", "radius: 7 mm"));
  EXPECT_EQ(e.where(), "guarded.yaml:5:57");
  EXPECT_EQ(e.key(), "bodies.particle.shape.radius");
  EXPECT_TRUE(contains(
      e.message(), "the bodies would have about 4.19e+12 points (body 'particle' about 4.19e+12"));
  EXPECT_TRUE(contains(e.message(), "limits.max_points, by default"));
  const InputError set = error_of(kCase, {parse_override("bodies.particle.shape.radius=7 mm")});
  EXPECT_EQ(set.where(), "--set bodies.particle.shape.radius");
}

TEST(InputGuards, ThePointCapIsConfigurable) {
  const InputError e = error_of(kCase + "limits: {max_points: 1000}\n");
  EXPECT_EQ(e.key(), "bodies.substrate.shape.radius");
  EXPECT_TRUE(contains(e.message(), "more than limits.max_points = 1e+03"));
  EXPECT_NO_THROW(load_case_text("guarded.yaml", kCase + "limits: {max_points: 1e5}\n"));
}

TEST(InputGuards, AGridBeyondItsCapIsRefusedAtTheCellSize) {
  const InputError e = error_of(kCase + "limits: {max_grid_nodes: 100}\n");
  EXPECT_EQ(e.where(), "guarded.yaml:13:14");
  EXPECT_EQ(e.key(), "grid.cell_size");
  EXPECT_TRUE(contains(e.message(), "about 8.39e+04 nodes (47 x 47 x 38 at cell size"));
  EXPECT_TRUE(contains(e.message(), "more than limits.max_grid_nodes = 100"));
}

// A density of 1e-30 kg/m^3 made the wave speed 1e20 m/s and the step 1e-27 s: the run never
// finished.
TEST(InputGuards, AStepCountBeyondItsCapIsRefusedAtTheEndTime) {
  const std::string light = "materials:\n  light: {base: al-ptw, density: 1e-30 kg/m^3}\n";
  const InputError e = error_of(edited("material: al-ptw\n    shape: {type: sphere",
                                       "material: light\n    shape: {type: sphere") +
                                light);
  EXPECT_EQ(e.where(), "guarded.yaml:15:13");
  EXPECT_EQ(e.key(), "solver.end_time");
  EXPECT_TRUE(contains(e.message(), "set by body 'particle': material light's wave speed"));
  EXPECT_TRUE(contains(e.message(), "more than limits.max_steps = 1e+08"));
  const InputError capped = error_of(kCase + "limits: {max_steps: 100}\n");
  EXPECT_TRUE(contains(capped.message(), "more than limits.max_steps = 100"));
}

// output.snapshot_interval: 1e-20 s made every step take a second (the schedule stepped through
// each interval).
TEST(InputGuards, AnOutputIntervalFarShorterThanAStepIsRefused) {
  const InputError e = error_of(kCase + "output: {snapshot_interval: 1e-20 s}\n");
  EXPECT_EQ(e.where(), "guarded.yaml:16:29");
  EXPECT_EQ(e.key(), "output.snapshot_interval");
  EXPECT_TRUE(contains(e.message(), "is less than a thousandth of the first time step"));
  const InputError history = error_of(kCase, {parse_override("output.history_interval=1e-20 s")});
  EXPECT_EQ(history.where(), "--set output.history_interval");
  // Below a step but not far below: an output every step, as a valid case may ask.
  EXPECT_NO_THROW(load_case_text("guarded.yaml", kCase + "output: {history_interval: 0}\n"));
  EXPECT_NO_THROW(load_case_text("guarded.yaml", kCase + "output: {history_interval: 0.001 ns}\n"));
}

// Errors that only the set-up finds named the file alone.
TEST(InputGuards, SetUpErrorsNameTheLineOfTheKey) {
  const Case overlap = load_case_text("guarded.yaml", edited("[0, 0, 7 um]", "[0, 0, 0]"));
  const InputError e = input_error([&] { run::build_solver_state(overlap); });
  EXPECT_EQ(e.where(), "guarded.yaml:5:5");
  EXPECT_EQ(e.key(), "bodies.particle.shape");
  EXPECT_TRUE(contains(e.message(), "overlaps body 'substrate'"));
  const Case outside = load_case_text(
      "guarded.yaml",
      edited(
          "  cell_size: 1.4 um\n",
          "  cell_size: 1.4 um\n  min: [-20 um, -20 um, -5 um]\n  max: [20 um, 20 um, 20 um]\n"));
  const InputError grid = input_error([&] { run::build_solver_state(outside); });
  EXPECT_EQ(grid.where(), "guarded.yaml:14:3");
  EXPECT_EQ(grid.key(), "grid.min");
  EXPECT_TRUE(contains(grid.message(), "body 'substrate' reaches outside the grid along z"));
}

}  // namespace
}  // namespace coldspray::case_file
