// Where each key of a case was given, kept in the Case (Case::key_locations) for the errors that
// only set-up finds, after the document is gone: bodies that overlap, a body outside the grid,
// one with no points. They name FILE:LINE:COLUMN (or "--set KEY") as the reader's errors do.
#pragma once

#include <map>
#include <string>
#include <string_view>

#include "case/case.hpp"
#include "case/document.hpp"

namespace coldspray::case_file {

// Every key path of the document (list items by name or index) and its location.
std::map<std::string, std::string> key_locations(const Document& doc);

// The location of `key` in the case, or of its nearest given ancestor (a default has no line of
// its own), or else the case's file.
std::string where(const Case& c, std::string_view key);

// InputError at where(c, key), naming the key.
[[noreturn]] void fail_at(const Case& c, const std::string& key, const std::string& message);

}  // namespace coldspray::case_file
