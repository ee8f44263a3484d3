// The message for an option a subcommand does not have: CLI11 says only "The following
// arguments were not expected: 700m/s --speed", or, when the misnamed option was a required one,
// "--velocity is required", which hides the typo. This names the unknown option and the one
// meant: a near spelling (--diamter), or a word people use for it (--speed for --velocity).
#pragma once

#include <CLI/CLI.hpp>
#include <optional>
#include <string>

namespace coldspray::cli {

// "unknown option --speed; did you mean --velocity?" for the first unknown option left over by
// the subcommand that was parsed (or by the app itself), if any.
std::optional<std::string> unknown_option_message(const CLI::App& app);

}  // namespace coldspray::cli
