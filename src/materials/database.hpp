// The built-in material database: data/materials/NAME.yaml, embedded at build time.
// Each file is a material in the case-file syntax (see docs/input-reference.md), with sources.
#pragma once

#include <map>
#include <string>

namespace coldspray::materials {

// YAML text of each built-in material, keyed by name ("al-ptw", "cu-jc", ...).
const std::map<std::string, std::string>& builtin_sources();

}  // namespace coldspray::materials
