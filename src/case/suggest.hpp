// "Did you mean ...?": the closest valid word to a misspelt key or value.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace coldspray::case_file {

// The candidate nearest to `word` in edit distance, if near enough to be a likely typo.
std::optional<std::string_view> closest(std::string_view word,
                                        std::span<const std::string_view> candidates);

// "unknown WHAT 'WORD'; did you mean 'X'?", or "... (expected one of: A, B, C)" when nothing is
// close.
std::string unknown_word(std::string_view what, std::string_view word,
                         std::span<const std::string_view> candidates);
std::string unknown_word(std::string_view what, std::string_view word,
                         const std::vector<std::string>& candidates);

// "a, b, c"
std::string join(std::span<const std::string_view> words);

}  // namespace coldspray::case_file
