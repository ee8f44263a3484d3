// Materials as a case uses them: user-defined ones (with an optional built-in `base:` whose
// values they override), and the resolution of the names bodies use.
#pragma once

#include <yaml-cpp/yaml.h>

#include <string>

#include "case/case.hpp"
#include "case/document.hpp"
#include "materials/material.hpp"

namespace coldspray::case_file {

// Reads the material map `node` at key path `path`. With `base: BUILTIN` the map overrides
// that built-in: maps merge key by key, and naming another `model:` (or the other elastic form)
// replaces that group. Groups given without a source get one naming the case file.
materials::Material read_material(const Document& doc, const YAML::Node& node,
                                  const std::string& path, const std::string& name);

// Replaces c.materials (everything under `materials:`) by the materials the bodies use, keyed
// by the name each body gives: its own definition, else the built-in of that name.
void resolve_body_materials(const Document& doc, Case& c);

}  // namespace coldspray::case_file
