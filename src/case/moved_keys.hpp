// Keys that moved to another place in the case file, with their new place: a file or a --set
// with the old key still reads, as if it gave the new one (issue 54 split the contact keys by
// solver: `contact.mpm`, `contact.peridynamics`, with the repulsion's constants from
// `peridynamics` under `contact.peridynamics.repulsion`). A checkpoint's case text from before a
// move restarts unchanged.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include "case/document.hpp"

namespace coldspray::case_file {

// The key path that a key path given the old way (e.g. "contact.peridynamics.beta") now is, or
// nullopt: the moved key itself or any key under it.
std::optional<std::string> moved_key(std::string_view path);

// Moves every old key of the tree to its new place, keeping its value's position for messages;
// InputError, naming both, where the tree gives the same key both ways.
void move_old_keys(Document& doc);

}  // namespace coldspray::case_file
