// A mutation fuzzer over the case reader (load_case_text: parse, --set, validate, size limits),
// in-process, seeded from every example case and the reproducers kept in tests/data/fuzz. It
// runs a fixed budget of inputs from a fixed seed, so a failure reproduces; under the sanitize
// preset (ASan + UBSan) a crash or undefined behaviour stops it. It asserts what
// docs/reliability.md promises: no crash, no input slower than kPerInputSeconds, and every
// InputError (exit status 2) carries a location and says what is wrong.
#include <gtest/gtest.h>

#include <array>
#include <chrono>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <random>
#include <string>
#include <string_view>
#include <vector>

#include "case/load.hpp"
#include "core/error.hpp"

namespace coldspray::case_file {
namespace {

namespace fs = std::filesystem;

constexpr int kInputs = 5000;
constexpr double kPerInputSeconds = 2.0;  // release runs take milliseconds; ASan, ten times more
constexpr const char* kName = "fuzzed.yaml";

// Tokens that make YAML and quantities interesting: structure, anchors, extreme numbers, units.
constexpr std::array<std::string_view, 36> kTokens{
    "&a ", "*a",     "<<: *a", "[",    "]",       "{",     "}",     ": ",     "- ",
    "\n",  "\n  ",   "#",      "'",    "\"",      ",",     "1e308", "-1e308", "1e-308",
    "0",   "-0",     "nan",    ".inf", "1e-20 s", "7 mm",  "20",    "um^12",  "m^13",
    "1/s", "kg/m^3", "~",      "null", "true",    "! tag", "? key", "|\n  x", "%YAML 1.2\n"};

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

std::string read_text(const fs::path& path) {
  std::ifstream in(path);
  return std::string((std::istreambuf_iterator<char>(in)), {});
}

std::vector<std::string> seeds() {
  std::vector<std::string> out;
  for (const char* folder : {COLDSPRAY_SOURCE_DIR "/examples", COLDSPRAY_TEST_DATA "/fuzz"})
    for (const auto& entry : fs::recursive_directory_iterator(folder))
      if (entry.path().extension() == ".yaml") out.push_back(read_text(entry.path()));
  std::sort(out.begin(), out.end());  // the directory order is not fixed; the budget's is
  return out;
}

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : random_(seed) {}

  std::size_t below(std::size_t n) { return n == 0 ? 0 : random_() % n; }

  void mutate(std::string& text) {
    const std::size_t at = below(text.size() + 1);
    switch (below(5)) {
      case 0:  // insert a token
        text.insert(at, kTokens[below(kTokens.size())]);
        break;
      case 1:  // delete a span
        text.erase(at, below(16) + 1);
        break;
      case 2: {  // duplicate a span
        const std::string span = text.substr(at, below(64) + 1);
        text.insert(below(text.size() + 1), span);
        break;
      }
      case 3:  // flip a byte
        if (at < text.size()) text[at] = static_cast<char>(random_() & 0xff);
        break;
      default:  // replace a number's digits by an extreme
        if (const std::size_t digit = text.find_first_of("0123456789", at);
            digit != std::string::npos)
          text.replace(digit, text.find_first_not_of("0123456789.e-", digit) - digit,
                       kTokens[15 + below(5)]);
    }
  }

  std::vector<Override> overrides() {
    std::vector<Override> out;
    for (std::size_t n = below(3); n > 0; --n)
      out.push_back(
          {std::string(kKeys[below(kKeys.size())]), std::string(kValues[below(kValues.size())])});
    return out;
  }

 private:
  std::mt19937_64 random_;
};

// "FILE:LINE:COLUMN", "FILE" for a value with no position, "--set KEY" or "builtin:NAME...".
bool located(const InputError& e) {
  return e.where().starts_with(kName) || e.where().starts_with("--set ") ||
         e.where().starts_with("builtin:");
}

TEST(CaseFuzz, NoCrashNoStallEveryErrorLocated) {
  const std::vector<std::string> corpus = seeds();
  ASSERT_GE(corpus.size(), 20u);
  Mutator m(20261203);
  int accepted = 0, refused = 0;
  for (int i = 0; i < kInputs; ++i) {
    std::string text = corpus[m.below(corpus.size())];
    for (std::size_t k = m.below(4) + 1; k > 0; --k) m.mutate(text);
    const std::vector<Override> overrides = m.overrides();
    const auto start = std::chrono::steady_clock::now();
    try {
      load_case_text(kName, text, {}, overrides);
      ++accepted;
    } catch (const InputError& e) {
      ++refused;
      EXPECT_TRUE(located(e)) << "input " << i << ": " << e.what() << "\n" << text;
      EXPECT_FALSE(e.message().empty()) << "input " << i;
    } catch (const std::exception& e) {
      ADD_FAILURE() << "input " << i << ": not an InputError: " << e.what() << "\n" << text;
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    EXPECT_LT(seconds, kPerInputSeconds) << "input " << i << "\n" << text;
  }
  // Both sides are exercised: some mutations keep a valid case, most break it.
  EXPECT_GT(accepted, 0);
  EXPECT_GT(refused, kInputs / 2);
}

}  // namespace
}  // namespace coldspray::case_file
