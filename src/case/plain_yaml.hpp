// The YAML a case is written in: plain trees. Anchors and aliases (&NAME, *NAME, and the merge
// key `<<: *NAME` built on them) are refused, since an alias makes the tree a graph: `&a [*a]`
// contains itself, and a few nested aliases in a short text stand for billions of nodes, which
// every walk of the tree would visit. Nesting is capped for the same reason: the walks of the
// tree recurse. docs/reliability.md, "Input that cannot crash or stall".
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>
#include <string_view>

namespace coldspray::case_file {

// Maps and lists nested deeper than this are refused; a case file needs about 5 levels.
inline constexpr int kMaxNesting = 32;

// Where YAML text came from: a file, whose problems are located FILE:LINE:COLUMN, or the value
// of `--set KEY=VALUE`, whose problems are located "--set KEY" (set `key`).
struct YamlSource {
  std::string name;  // the file, or "--set KEY"
  std::string key;   // the key a --set value is for; empty for a file
};

// Parses the first document of `text`; InputError at `source` when it is not valid YAML, uses
// an anchor or an alias, or nests deeper than kMaxNesting.
YAML::Node load_plain_yaml(std::string_view text, const YamlSource& source);

}  // namespace coldspray::case_file
