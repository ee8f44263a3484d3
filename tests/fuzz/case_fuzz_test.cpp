// A mutation fuzzer over the case reader (load_case_text: parse, --set, validate, size limits),
// in-process, seeded from every example case and the reproducers kept in tests/data/fuzz. It
// runs a fixed budget of inputs from a fixed seed, so a failure reproduces; under the sanitize
// preset (ASan + UBSan) a crash or undefined behaviour stops it. It asserts what
// docs/reliability.md promises: no crash, no input slower than kPerInputSeconds, and every
// InputError (exit status 2) carries a location and says what is wrong.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <string>
#include <string_view>
#include <vector>

#include "case/load.hpp"
#include "core/error.hpp"
#include "fuzz_support.hpp"

namespace coldspray::case_file {
namespace {

constexpr int kInputs = 5000;
constexpr const char* kName = "fuzzed.yaml";

// Keys a --set mutation targets, and values it gives them.
constexpr std::array<std::string_view, 14> kKeys{"solver.cfl",
                                                 "solver.end_time",
                                                 "solver.method",
                                                 "bodies.0.spacing",
                                                 "bodies.0.shape.radius",
                                                 "bodies.particle.velocity",
                                                 "bodies.1.shape",
                                                 "grid.cell_size",
                                                 "grid.min",
                                                 "output.snapshot_interval",
                                                 "output.history_interval",
                                                 "limits.max_points",
                                                 "materials.m",
                                                 "a.b.c.d.e.f"};
constexpr std::array<std::string_view, 14> kValues{"0.5",
                                                   "1e-20 s",
                                                   "7 mm",
                                                   "&a [*a]",
                                                   "[0, 0, -1e308 m/s]",
                                                   "{type: box}",
                                                   "[]",
                                                   "{}",
                                                   "1e15",
                                                   "{base: al-ptw, density: 1e-30 kg/m^3}",
                                                   "peridynamics",
                                                   "-1",
                                                   "20",
                                                   "[[[[[[[[[[1]]]]]]]]]]"};

// Every example, and the case reproducers at the top of tests/data/fuzz (its folders hold the
// other fuzzers' seeds).
std::vector<std::string> seeds() {
  std::vector<std::string> out = fuzz::yaml_texts({COLDSPRAY_SOURCE_DIR "/examples"});
  for (std::string& text : fuzz::yaml_texts({COLDSPRAY_TEST_DATA "/fuzz"}, false))
    out.push_back(std::move(text));
  std::sort(out.begin(), out.end());  // as the budget's draws were before the folders
  return out;
}

// Up to two --set overrides drawn from kKeys and kValues.
std::vector<Override> overrides(fuzz::Mutator& m) {
  std::vector<Override> out;
  for (std::size_t n = m.below(3); n > 0; --n)
    out.push_back({std::string(m.pick(kKeys)), std::string(m.pick(kValues))});
  return out;
}

// "FILE:LINE:COLUMN", "FILE" for a value with no position, "--set KEY" or "builtin:NAME...".
bool located(const InputError& e) {
  return e.where().starts_with(kName) || e.where().starts_with("--set ") ||
         e.where().starts_with("builtin:");
}

TEST(CaseFuzz, NoCrashNoStallEveryErrorLocated) {
  const std::vector<std::string> corpus = seeds();
  ASSERT_GE(corpus.size(), 20u);
  fuzz::Mutator m(20261203);
  int accepted = 0, refused = 0;
  for (int i = 0; i < kInputs; ++i) {
    std::string text = corpus[m.below(corpus.size())];
    for (std::size_t k = m.below(4) + 1; k > 0; --k) m.mutate(text);
    const std::vector<Override> sets = overrides(m);
    const auto start = std::chrono::steady_clock::now();
    try {
      load_case_text(kName, text, {}, sets);
      ++accepted;
    } catch (const InputError& e) {
      ++refused;
      EXPECT_TRUE(located(e)) << "input " << i << ": " << e.what() << "\n" << text;
      EXPECT_FALSE(e.message().empty()) << "input " << i;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "input " << i << ": not an InputError: " << e.what() << "\n" << text;
    }
    const double seconds = fuzz::seconds_since(start);
    EXPECT_LT(seconds, fuzz::kPerInputSeconds) << "input " << i << "\n" << text;
  }
  // Both sides are exercised: some mutations keep a valid case, most break it.
  EXPECT_GT(accepted, 0);
  EXPECT_GT(refused, kInputs / 2);
}

}  // namespace
}  // namespace coldspray::case_file
