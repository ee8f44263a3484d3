// The validator of arguments and options that name a file or folder to read or write (the case,
// --out, --write-case, --restart, --initial-state): the value given must not be empty. Empty is
// how the commands tell "not given", so `--write-case ''` (a script's unset variable) ran the
// whole simulation it meant to write, `material-test --out ''` ended in an internal error, and
// `check ''` said "error: no such file", naming nothing (docs/reliability.md).
#pragma once

#include <CLI/CLI.hpp>

namespace coldspray::cli {

CLI::Validator given_path();

}  // namespace coldspray::cli
