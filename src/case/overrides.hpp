// `--set KEY=VALUE`: edits of the case's YAML tree before it is read.
#pragma once

#include "case/document.hpp"
#include "case/load.hpp"

namespace coldspray::case_file {

// Puts the override's value at its key path: map keys are created when missing, list items are
// selected by `name` or index. The new nodes are marked as coming from "--set KEY".
void apply_override(Document& doc, const Override& o);

}  // namespace coldspray::case_file
