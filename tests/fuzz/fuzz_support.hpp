// What the fuzz tests (tests/fuzz/*_fuzz_test.cpp) share: their seeds' texts, the byte-level
// mutations of a text, a clock for the per-input time bound, and the budget scale under the
// sanitizers. Every fuzzer draws from a fixed seed, so a failure reproduces.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <random>
#include <string>
#include <string_view>
#include <vector>

namespace coldspray::fuzz {

// ASan and UBSan (the sanitize preset) make the readers 2 to 4 times slower and a run of the
// binary about 9 times (measured, docs/reliability.md): the fuzzers run a smaller budget there,
// so the preset's test run stays short. GCC defines __SANITIZE_ADDRESS__ under
// -fsanitize=address; Clang answers __has_feature.
#if defined(__SANITIZE_ADDRESS__)
inline constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
inline constexpr bool kSanitized = true;
#else
inline constexpr bool kSanitized = false;
#endif
#else
inline constexpr bool kSanitized = false;
#endif

// `release` inputs in the release build, `sanitized` under the sanitizers.
constexpr int budget(int release, int sanitized) { return kSanitized ? sanitized : release; }

// The most an input may take to be read: release runs take milliseconds, ASan a few times more;
// an input near this bound is a stall in the making (the 100 000 keys once took 48 s).
inline constexpr double kPerInputSeconds = 2.0;

// The texts of the .yaml files in `folders` (and in their subfolders if `recursive`), sorted:
// the directory order is not fixed, the budget's draws must be.
std::vector<std::string> yaml_texts(const std::vector<std::filesystem::path>& folders,
                                    bool recursive = true);

// Tokens that make YAML and quantities interesting: structure, anchors, extreme numbers, units.
// kTokens[kExtremes, kExtremes + 5) are the extreme numbers a number's digits are replaced by.
inline constexpr std::size_t kExtremes = 15;
inline constexpr std::array<std::string_view, 36> kTokens{
    "&a ", "*a",     "<<: *a", "[",    "]",       "{",     "}",     ": ",     "- ",
    "\n",  "\n  ",   "#",      "'",    "\"",      ",",     "1e308", "-1e308", "1e-308",
    "0",   "-0",     "nan",    ".inf", "1e-20 s", "7 mm",  "20",    "um^12",  "m^13",
    "1/s", "kg/m^3", "~",      "null", "true",    "! tag", "? key", "|\n  x", "%YAML 1.2\n"};

// Values as a user might type them, or a probe (Mutator::hostile_value draws from all three):
// numbers at the edge of their syntax, units, and YAML structure, anchors and aliases.
inline constexpr std::array<std::string_view, 30> kHostileNumbers{
    "",     " ",       "=",      "==",     "0.5", "1e",         "1e+",         "0x10",       "0o7",
    "0b1",  "1e400",   "-1e400", "1e-400", "nan", "NaN",        ".nan",        "inf",        "-inf",
    ".inf", "+2",      "-0",     "1_000",  "1,5", "2147483648", "-2147483649", "4294967296", "3.5",
    "1.0",  "1e-20 s", "7 mm"};
// Units, and the bytes of other encodings: a byte-order mark, invalid UTF-8, control characters.
inline constexpr std::array<std::string_view, 18> kHostileUnits{
    "7 m^+2",      "7 um^12",     "7 um^13",       "7 m^-12", "7 m^",  "7 ^2",
    "7 mm/",       "7 /s",        "7 m/s/s/s",     "7 kg*",   "m",     "1 um^2147483648",
    "7 \xc2\xb5m", "7 \xce\xbcm", "\357\273\2771", "\xff",    "1\x01", "a\tb"};
inline constexpr std::array<std::string_view, 32> kHostileYaml{"&a 1",
                                                               "*a",
                                                               "&a [*a]",
                                                               "<<: *a",
                                                               "!tag 1",
                                                               "!!str 1",
                                                               "!!binary x",
                                                               "!!int 1.5",
                                                               "? a",
                                                               "- a",
                                                               "|\n x",
                                                               ">\n x",
                                                               "'unterminated",
                                                               "\"unterminated",
                                                               "\"\\x00\"",
                                                               "\"\\uD800\"",
                                                               "[1, 2",
                                                               "{a: 1",
                                                               "a: b: c",
                                                               "--- 1\n--- 2",
                                                               "...",
                                                               "%YAML 1.2",
                                                               "[0, 0, -7 m/s]",
                                                               "[0, 0]",
                                                               "[nan, -inf]",
                                                               "{type: box}",
                                                               "{radius: -1 um}",
                                                               "[]",
                                                               "{}",
                                                               "~",
                                                               "null",
                                                               "peridynamics"};

class Mutator {
 public:
  explicit Mutator(std::uint64_t seed) : random_(seed) {}

  // A draw from [0, n), 0 for n = 0.
  std::size_t below(std::size_t n) { return n == 0 ? 0 : random_() % n; }
  template <class List>
  auto pick(const List& list) -> decltype(list[0]) {
    return list[below(list.size())];
  }

  // One of kHostileNumbers, kHostileUnits and kHostileYaml, each value as likely.
  std::string_view hostile_value();

  // One mutation of `text`: a token inserted, a span deleted or duplicated, a byte flipped, or a
  // number's digits replaced by an extreme.
  void mutate(std::string& text);

 private:
  std::mt19937_64 random_;
};

// Seconds since `start` on the steady clock.
inline double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace coldspray::fuzz
