// Keys that case files no longer take, with what replaced them: an old file gets that in its
// error (exit 2), not just "unknown key".
#pragma once

#include <optional>
#include <string_view>

namespace coldspray::case_file {

// Why the key at `path` (e.g. "metrics.bonded_pbcp") was retired and what to use instead, if it
// was.
std::optional<std::string_view> retired_key(std::string_view path);

}  // namespace coldspray::case_file
