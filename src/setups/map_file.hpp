// A setup file (`coldspray deposit`, `coldspray calibrate`) read as YAML whose top level must be
// a map of keys: the check both readers make before they read their keys.
#pragma once

#include <string>

#include "case/document.hpp"
#include "core/error.hpp"

namespace coldspray::setups {

// The file at `path`; InputError where it is unreadable, not YAML or not a map at its top level.
inline case_file::Document read_map_file(const std::string& path) {
  case_file::Document doc = case_file::Document::from_file(path);
  const case_file::Document& read = doc;
  if (!read.root().IsMap())
    throw InputError(read.where(read.root()), "",
                     "expected a map of keys, got " + case_file::describe(read.root()));
  return doc;
}

}  // namespace coldspray::setups
