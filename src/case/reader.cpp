#include "case/reader.hpp"

#include <unordered_map>

#include "case/case_materials.hpp"
#include "case/retired_keys.hpp"
#include "case/shortest_number.hpp"
#include "case/suggest.hpp"
#include "core/error.hpp"

namespace coldspray::case_file {

Reader::Reader(const Document& doc, const YAML::Node& map, std::string path, bool overlay)
    : doc_(doc), map_(map), path_(std::move(path)), overlay_(overlay) {
  if (!map.IsMap()) {
    throw InputError(doc_.where(map), path_, "expected a map of keys, got " + describe(map));
  }
  // Each name's entry, by a hash lookup: a map of many keys is read in time linear in them.
  std::unordered_map<std::string, std::size_t> seen;
  for (const auto& entry : map) {
    if (!entry.first.IsScalar()) {
      throw InputError(doc_.where(entry.first), path_,
                       "a key must be a plain name, got " + describe(entry.first));
    }
    const std::string& name = entry.first.Scalar();
    if (const auto [earlier, fresh] = seen.emplace(name, entries_.size()); !fresh) {
      const Entry& first = entries_[earlier->second];
      throw InputError(doc_.where(entry.first, entry.second), path_of(name),
                       "duplicate key '" + name + "' (first given at " +
                           doc_.where(first.key, first.value) + ")");
    }
    entries_.push_back({entry.first, entry.second, name});
  }
}

void Reader::quantity(std::string_view key, double& value, units::Dimension dimension,
                      Presence presence, const Range& range) {
  if (const Entry* e = find(key, presence)) {
    value = to_quantity(e->value, where_value(*e), key, dimension, range, "");
  }
}

void Reader::quantity(std::string_view key, std::optional<double>& value,
                      units::Dimension dimension, Presence presence, const Range& range) {
  if (const Entry* e = find(key, presence)) {
    value = to_quantity(e->value, where_value(*e), key, dimension, range, "");
  }
}

void Reader::vector(std::string_view key, Vec3& value, units::Dimension dimension,
                    Presence presence) {
  if (const Entry* e = find(key, presence)) value = to_vector(*e, key, dimension);
}

void Reader::vector(std::string_view key, std::optional<Vec3>& value, units::Dimension dimension,
                    Presence presence) {
  if (const Entry* e = find(key, presence)) value = to_vector(*e, key, dimension);
}

void Reader::materials(std::string_view key, std::map<std::string, materials::Material>& values) {
  const Entry* e = find(key, kOptional);
  if (!e) return;
  const Reader entries(doc_, map_node(*e), path_of(key), false);
  values.clear();
  for (const Entry& entry : entries.entries_) {
    values[entry.name] =
        read_material(doc_, entries.map_node(entry), entries.path_of(entry.name), entry.name);
  }
}

void Reader::check(bool ok, std::string_view key, std::string_view message) const {
  if (ok) return;
  const Entry* e = find(key, kOptional);
  throw InputError(e ? where_value(*e) : doc_.where(map_), path_of(key), std::string(message));
}

const Reader::Entry* Reader::find(std::string_view key, Presence presence) const {
  for (const Entry& e : entries_) {
    if (e.name == key) return &e;
  }
  if (presence == kRequired && !overlay_) missing(key, "");
  return nullptr;
}

void Reader::missing(std::string_view key, const std::string& hint) const {
  throw InputError(doc_.where(map_), path_of(key),
                   "missing required key '" + std::string(key) + "'" + hint);
}

void Reader::reject_unknown(std::span<const std::string_view> known) const {
  for (const Entry& e : entries_) {
    if (std::find(known.begin(), known.end(), e.name) == known.end()) {
      const std::string path = path_of(e.name);
      const auto retired = retired_key(path);
      throw InputError(doc_.where(e.key, e.value), path,
                       retired ? std::string(*retired) : unknown_word("key", e.name, known));
    }
  }
}

std::size_t Reader::choose(std::string_view tag, std::span<const std::string_view> names,
                           std::size_t current) const {
  const Entry* e = find(tag, kOptional);
  if (!e) {
    if (overlay_) return current;
    missing(tag, " (one of: " + join(names) + ")");
  }
  const YAML::Node& node = scalar_node(*e, "one of: " + join(names));
  const auto it = std::find(names.begin(), names.end(), node.Scalar());
  if (it == names.end()) fail(node, tag, unknown_word(std::string(tag), node.Scalar(), names));
  return static_cast<std::size_t>(it - names.begin());
}

void Reader::claim_name(const YAML::Node& item, const std::string& path,
                        std::map<std::string, std::string>& names) const {
  if (!item.IsMap() || !item["name"] || !item["name"].IsScalar()) return;
  const YAML::Node name = item["name"];
  const auto [first, inserted] = names.emplace(name.Scalar(), doc_.where(name));
  if (!inserted) {
    throw InputError(
        doc_.where(name), path + ".name",
        "duplicate name '" + name.Scalar() + "' (first given at " + first->second + ")");
  }
}

bool Reader::has_any(const YAML::Node& map, std::span<const std::string_view> keys) {
  for (const auto& entry : map) {
    if (std::find(keys.begin(), keys.end(), entry.first.Scalar()) != keys.end()) return true;
  }
  return false;
}

const YAML::Node& Reader::scalar_node(const Entry& e, const std::string& expected) const {
  if (!e.value.IsScalar()) {
    fail(e, e.name, "expected " + expected + ", got " + describe(e.value));
  }
  return e.value;
}

const YAML::Node& Reader::list_node(const Entry& e, const std::string& expected) const {
  if (!e.value.IsSequence()) {
    fail(e, e.name, "expected " + expected + ", got " + describe(e.value));
  }
  return e.value;
}

const YAML::Node& Reader::map_node(const Entry& e) const {
  if (!e.value.IsMap()) fail(e, e.name, "expected a map of keys, got " + describe(e.value));
  return e.value;
}

double Reader::to_quantity(const YAML::Node& node, const std::string& where, std::string_view key,
                           units::Dimension dimension, const Range& range,
                           std::string_view component) const {
  const std::string expected = dimension == units::kDimensionless
                                   ? "a number"
                                   : "a " + units::dimension_name(dimension) + " such as '1 " +
                                         units::si_unit(dimension) + "'";
  if (!node.IsScalar()) {
    throw InputError(where, path_of(key),
                     std::string(component) + "expected " + expected + ", got " + describe(node));
  }
  double value = 0.0;
  try {
    value = units::parse_as(node.Scalar(), dimension);
  } catch (const UnitError& e) {
    throw InputError(where, path_of(key), std::string(component) + e.what());
  }
  if (!range.contains(value)) {
    std::string got = "'" + node.Scalar() + "'";
    if (dimension != units::kDimensionless) {
      got += " (" + shortest_text(value) + " " + units::si_unit(dimension) + ")";
    }
    throw InputError(where, path_of(key),
                     std::string(component) + "must be " + range.describe() + ", got " + got);
  }
  return value;
}

Vec3 Reader::to_vector(const Entry& e, std::string_view key, units::Dimension dimension) const {
  const std::string expected = "a list of 3 values [x, y, z]";
  if (!e.value.IsSequence() || e.value.size() != 3) {
    fail(e, key,
         "expected " + expected + ", got " +
             (e.value.IsSequence() ? std::to_string(e.value.size()) + " values"
                                   : describe(e.value)));
  }
  constexpr std::array<std::string_view, 3> kComponents{"x: ", "y: ", "z: "};
  Vec3 v;
  for (std::size_t i = 0; i < 3; ++i) {
    const YAML::Node component = e.value[i];
    v[static_cast<Eigen::Index>(i)] =
        to_quantity(component, doc_.where(component), key, dimension, kAnyValue, kComponents[i]);
  }
  return v;
}

std::string Reader::path_of(std::string_view key) const {
  return path_.empty() ? std::string(key) : path_ + "." + std::string(key);
}

std::string Reader::where_value(const Entry& e) const {
  // An empty value has no position of its own; its key has.
  return e.value.IsNull() ? doc_.where(e.key, e.value) : doc_.where(e.value);
}

void Reader::fail(const Entry& e, std::string_view key, const std::string& message) const {
  throw InputError(where_value(e), path_of(key), message);
}

void Reader::fail(const YAML::Node& node, std::string_view key, const std::string& message) const {
  throw InputError(doc_.where(node), path_of(key), message);
}

}  // namespace coldspray::case_file
