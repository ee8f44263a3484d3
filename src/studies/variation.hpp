// What a sweep varies: `--vary KEY=V1,V2,...` or `--vary KEY=START:STOP:STEP`, and the Cartesian
// product of several of them, each combination a list of `--set` style overrides.
#pragma once

#include <string>
#include <vector>

#include "case/load.hpp"

namespace coldspray::studies {

// The most values a range gives, and the most combinations a sweep runs: more cases than anyone
// waits for, and each costs a folder and a line of the table (docs/reliability.md).
inline constexpr long kMaxSweepCases = 100000;

struct Variation {
  std::string key;                  // a case-file key path, as for --set
  std::vector<std::string> values;  // each as --set would take it (units allowed)
};

// Parses "KEY=V1,V2,..." (commas inside [...] do not split, so vectors can be listed) or
// "KEY=START:STOP:STEP" (quantities of one dimension, STEP > 0, STOP included when it falls on
// the grid; the values are written as SI numbers). Throws InputError naming `--vary`.
Variation parse_variation(const std::string& text);

// The Cartesian product, the last variation varying fastest; InputError naming `--vary` beyond
// kMaxSweepCases combinations.
std::vector<std::vector<case_file::Override>> combinations(const std::vector<Variation>& vary);

}  // namespace coldspray::studies
