// Reading case files and materials: the public entry points of case/.
// Every failure is an InputError naming file:line:column (or "--set KEY") and the key path.
#pragma once

#include <iosfwd>
#include <string>
#include <string_view>
#include <vector>

#include "case/case.hpp"

namespace coldspray::case_file {

// One `--set KEY=VALUE`: KEY a dotted path (list items selected by their `name`, or by index),
// VALUE a YAML scalar or flow sequence/map ("700 m/s", "[0, 0, -700 m/s]").
struct Override {
  std::string key;
  std::string value;
};

// Splits "KEY=VALUE"; throws InputError (where = "--set") when there is no '=' or no key.
Override parse_override(std::string_view text);

// Reads, overrides, parses and validates a case file. Throws InputError on any problem.
Case load_case(const std::string& path, const std::vector<Override>& overrides = {});

// Where a value of a generated case came from: problems with the value at `key` (a dotted path
// as in --set, list items by name or index) are reported at `origin` (e.g. "--diameter")
// rather than at a line of text the user did not write.
struct ValueOrigin {
  std::string key;
  std::string origin;
};

// load_case for a case given as YAML text (`coldspray impact` generates one): the same reading,
// overrides and checks. `name` stands for the file in messages and is the case's source_file.
Case load_case_text(const std::string& name, std::string_view text,
                    const std::vector<ValueOrigin>& origins = {},
                    const std::vector<Override>& overrides = {});

// The `limits` section the overrides give (`--set limits.KEY=VALUE`; the others are ignored),
// read and checked as a case's: for a generator that sizes its case before it writes it
// (`coldspray deposit`). InputError at "--set KEY" for a bad value.
Limits limits_of_overrides(const std::vector<Override>& overrides);

// YAML text with the overrides applied, re-emitted (comments are lost); InputError as load_case.
std::string apply_overrides(const std::string& name, std::string_view text,
                            const std::vector<Override>& overrides);

// The fully resolved case (defaults filled in, SI numbers, materials expanded), as YAML that
// load_case reads back to an equal Case.
void write_resolved(const Case& c, std::ostream& out);

// Built-in materials (data/materials/*.yaml).
std::vector<std::string> builtin_material_names();
// InputError if unknown, located at `where` (the option that named it, or nothing).
materials::Material builtin_material(const std::string& name, const std::string& where = "");

// "NAME" for a built-in, or "CASE.yaml:NAME" for a material of a case file's `materials:`; an
// unknown built-in is reported at `where` (`material-test --material`), one of the file in it.
materials::Material resolve_material(const std::string& reference, const std::string& where = "");

// Every parameter of a material with its SI unit, grouped by sub-model, with each group's source.
void print_material(const materials::Material& m, std::ostream& out);

}  // namespace coldspray::case_file
