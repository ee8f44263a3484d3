// A mutation fuzzer over the deposit file's reader (setups::read_deposit_file: parse, schema, the
// size distribution, the grid, the size-similar set-up's defaults), seeded from the example
// deposits and those in tests/data/fuzz/deposit (its refused/ folder: reproducers, each refused).
// Only the reading: the placement of the particles is left out. Each mutated text is written to
// a file, since the reader reads a path. It asserts what docs/reliability.md promises: no crash,
// no input slower than kPerInputSeconds, and every refusal an InputError located at the file
// (FILE:LINE:COLUMN, or FILE) with a message.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "core/error.hpp"
#include "fuzz_support.hpp"
#include "setups/deposit_file.hpp"
#include "temp_dir.hpp"

namespace coldspray::setups {
namespace {

namespace fs = std::filesystem;

const int kDepositInputs = fuzz::budget(3000, 1000);

// Valid deposit files; tests/data/fuzz/deposit/refused holds the reproducers, each refused.
std::vector<std::string> deposit_seeds() {
  return fuzz::yaml_texts(
      {COLDSPRAY_SOURCE_DIR "/examples/deposit", COLDSPRAY_TEST_DATA "/fuzz/deposit"}, false);
}

// The value of a random `key: value` (the rest of its line) replaced by a hostile value.
void replace_a_value(fuzz::Mutator& m, std::string& text) {
  const std::size_t colon = text.find(": ", m.below(text.size()));
  if (colon == std::string::npos) return;
  const std::size_t end = text.find('\n', colon);
  text.replace(colon + 2, end == std::string::npos ? end : end - colon - 2, m.hostile_value());
}

// Reads `text` from a file at `path`: counts it as accepted, or checks the refusal.
void read_one(const std::string& path, const std::string& text, int input, int& accepted) {
  std::ofstream(path, std::ios::binary | std::ios::trunc) << text;
  const auto start = std::chrono::steady_clock::now();
  try {
    read_deposit_file(path);
    ++accepted;
  } catch (const InputError& e) {
    EXPECT_TRUE(e.where().starts_with(path)) << "input " << input << ": " << e.what() << "\n"
                                             << text;
    EXPECT_FALSE(e.message().empty()) << "input " << input << "\n" << text;
  } catch (const std::exception& e) {
    ADD_FAILURE() << "input " << input << ": not an InputError: " << e.what() << "\n" << text;
  }
  EXPECT_LT(fuzz::seconds_since(start), fuzz::kPerInputSeconds) << "input " << input << "\n"
                                                                << text;
}

TEST(DepositFuzz, SeedsAreAccepted) {
  const std::string path = testing::make_temp_dir("deposit-fuzz") + "/deposit.yaml";
  int accepted = 0;
  const std::vector<std::string> corpus = deposit_seeds();
  ASSERT_GE(corpus.size(), 3u);
  for (const std::string& text : corpus) read_one(path, text, -1, accepted);
  EXPECT_EQ(accepted, static_cast<int>(corpus.size()));
}

TEST(DepositFuzz, ReproducersAreRefusedAtTheFile) {
  const std::string path = testing::make_temp_dir("deposit-fuzz") + "/deposit.yaml";
  int accepted = 0;
  const std::vector<std::string> refused =
      fuzz::yaml_texts({COLDSPRAY_TEST_DATA "/fuzz/deposit/refused"});
  ASSERT_FALSE(refused.empty());
  for (const std::string& text : refused) read_one(path, text, -1, accepted);
  EXPECT_EQ(accepted, 0);
}

TEST(DepositFuzz, NoCrashNoStallEveryErrorAtTheFile) {
  const std::string path = testing::make_temp_dir("deposit-fuzz") + "/deposit.yaml";
  const std::vector<std::string> corpus = deposit_seeds();
  fuzz::Mutator m(20261205);
  int accepted = 0;
  for (int i = 0; i < kDepositInputs; ++i) {
    std::string text = m.pick(corpus);
    for (std::size_t k = m.below(3) + 1; k > 0; --k) {
      if (m.below(3) == 0)
        replace_a_value(m, text);
      else
        m.mutate(text);
    }
    read_one(path, text, i, accepted);
  }
  // Both sides are exercised: some mutations keep a valid file, most break it.
  EXPECT_GT(accepted, 0);
  EXPECT_LT(accepted, kDepositInputs / 2);
}

}  // namespace
}  // namespace coldspray::setups
