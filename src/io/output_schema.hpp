// A JSON output declared as fields, the way the case schema (case/case_schema.hpp) declares the
// keys it parses and echoes: each field names its JSON key, its unit (stated here once, for the
// docs' field tables) and how to read it from the value written. The writer emits the fields in
// declared order, so the bytes depend only on the declaration.
#pragma once

#include <filesystem>
#include <functional>
#include <nlohmann/json.hpp>
#include <ostream>
#include <string>
#include <utility>
#include <vector>

#include "io/atomic_file.hpp"

namespace coldspray::io {

template <class T>
struct OutputField {
  std::string name;
  std::string unit;  // "-" for a count, a flag or a name
  std::function<nlohmann::ordered_json(const T&)> value;
  // A key that the value itself names (summary.json's cell_size or horizon); empty: `name`.
  std::function<std::string(const T&)> key = {};
};

template <class T>
using OutputFields = std::vector<OutputField<T>>;

// Fields' dotted names with their units, in written order: a docs/outputs.md table's rows.
using FieldUnits = std::vector<std::pair<std::string, std::string>>;

// The fields of `t`, in declared order; a field whose value is discarded (a JSON "discarded"
// value) is left out, for the fields only one solver has.
template <class T>
nlohmann::ordered_json write_fields(const OutputFields<T>& fields, const T& t) {
  nlohmann::ordered_json j = nlohmann::ordered_json::object();
  for (const OutputField<T>& f : fields) {
    nlohmann::ordered_json v = f.value(t);
    if (!v.is_discarded()) j[f.key ? f.key(t) : f.name] = std::move(v);
  }
  return j;
}

// The value that leaves a field out of write_fields' object.
inline nlohmann::ordered_json absent_field() {
  return nlohmann::ordered_json(nlohmann::ordered_json::value_t::discarded);
}

// Each field's dotted name under `prefix` and its unit, for the docs' field tables.
template <class T>
void append_field_units(const OutputFields<T>& fields, const std::string& prefix, FieldUnits& out) {
  for (const OutputField<T>& f : fields) out.emplace_back(prefix + f.name, f.unit);
}

// The fields of `t` as the file at `path` (written atomically), indented by `indent` spaces, with
// a final newline.
template <class T>
void write_fields_file(const std::filesystem::path& path, const OutputFields<T>& fields, const T& t,
                       int indent = 2) {
  const nlohmann::ordered_json j = write_fields(fields, t);
  write_atomically(path, [&](std::ostream& out) { out << j.dump(indent) << "\n"; });
}

// The fields' names and units, for a file of one level.
template <class T>
FieldUnits field_units(const OutputFields<T>& fields) {
  FieldUnits out;
  append_field_units(fields, "", out);
  return out;
}

}  // namespace coldspray::io
