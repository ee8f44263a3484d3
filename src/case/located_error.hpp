// The errors that only set-up finds, after the document is gone: bodies that overlap, a body
// outside the grid, one with no points. They name the key's FILE:LINE:COLUMN (or "--set KEY"),
// kept in the Case (Case::key_locations, filled by case/key_locations.hpp), as the reader's errors
// do. Without the YAML reader: the solvers' set-up raises them and includes no yaml-cpp.
#pragma once

#include <string>
#include <string_view>

#include "case/case.hpp"

namespace coldspray::case_file {

// The location of `key` in the case, or of its nearest given ancestor (a default has no line of
// its own), or else the case's file.
std::string where(const Case& c, std::string_view key);

// InputError at where(c, key), naming the key.
[[noreturn]] void fail_at(const Case& c, const std::string& key, const std::string& message);

}  // namespace coldspray::case_file
