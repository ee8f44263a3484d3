// Where each key of a case was given, read from its document into the Case (Case::key_locations)
// for the errors that only set-up finds, after the document is gone (case/located_error.hpp).
#pragma once

#include <map>
#include <string>

#include "case/document.hpp"

namespace coldspray::case_file {

// Every key path of the document (list items by name or index) and its location.
std::map<std::string, std::string> key_locations(const Document& doc);

}  // namespace coldspray::case_file
