// Reads YAML maps into structs by their schema (the `fields` functions of case_schema.hpp and
// material_schema.hpp): units, defaults, ranges, unknown and duplicate keys, variants chosen by
// a tag key. Every error is an InputError located at the offending node.
#pragma once

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <array>
#include <map>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "case/case.hpp"
#include "case/codecs.hpp"
#include "case/document.hpp"
#include "case/field_rules.hpp"
#include "case/key_list.hpp"
#include "core/units.hpp"
#include "materials/material.hpp"

namespace coldspray::case_file {

// The alternative of a variant with the given index, default-constructed.
template <class Variant, std::size_t... I>
Variant make_alternative(std::size_t index, std::index_sequence<I...>) {
  static constexpr Variant (*kMakers[])() = {+[] { return Variant(std::in_place_index<I>); }...};
  return kMakers[index]();
}

class Reader {
 public:
  // Reads the map `node`, found at key path `path`, into `target`. With `overlay`, absent keys
  // keep target's values, even required ones (a material over its base). `extra_keys` are
  // accepted without being read: the caller handles them.
  template <class T>
  static void read(const Document& doc, const YAML::Node& node, const std::string& path, T& target,
                   bool overlay = false, std::span<const std::string_view> extra_keys = {}) {
    Reader reader(doc, node, path, overlay);
    reader.read_into(target, extra_keys);
  }

  // A scalar turned into a value by a codec (codecs.hpp).
  template <class T, class Codec>
  void scalar(std::string_view key, T& value, const Codec& codec, Presence presence) {
    if (const Entry* e = find(key, presence)) {
      parse_with(codec, scalar_node(*e, codec.expected()), value, key);
    }
  }

  // A list of scalars, each turned into a value by a codec; no value may appear twice.
  template <class T, class Codec>
  void scalars(std::string_view key, std::vector<T>& values, const Codec& codec,
               Presence presence) {
    const Entry* e = find(key, presence);
    if (!e) return;
    const YAML::Node& list = list_node(*e, "a list of " + codec.expected());
    values.clear();
    for (const YAML::Node& item : list) {
      if (!item.IsScalar()) {
        fail(item, key, "expected " + codec.expected() + ", got " + describe(item));
      }
      T value{};
      parse_with(codec, item, value, key);
      if (std::find(values.begin(), values.end(), value) != values.end()) {
        fail(item, key, "'" + item.Scalar() + "' is listed twice");
      }
      values.push_back(value);
    }
  }

  // A map from scalar keys to scalar values, each side turned into a value by its codec.
  template <class K, class V, class KeyCodec, class ValueCodec>
  void table(std::string_view key, std::map<K, V>& values, const KeyCodec& key_codec,
             const ValueCodec& value_codec) {
    if (!overlay_) values.clear();
    read_table(key, values, key_codec, value_codec);
  }

  // The same, keyed by an enumeration: every enumerator gets an entry, `fill` if not given.
  template <class K, std::size_t N, class V, class ValueCodec>
  void table(std::string_view key, std::map<K, V>& values, const Names<K, N>& key_names,
             const ValueCodec& value_codec, const V& fill) {
    if (!overlay_) {
      values.clear();
      for (const auto& [name, k] : key_names.entries) values[k] = fill;
    }
    read_table(key, values, key_names, value_codec);
  }

  // A number with a unit of the given dimension (a bare number is SI), within `range`.
  void quantity(std::string_view key, double& value, units::Dimension dimension, Presence presence,
                const Range& range = kAnyValue);
  void quantity(std::string_view key, std::optional<double>& value, units::Dimension dimension,
                Presence presence, const Range& range = kAnyValue);

  // [x, y, z], each element a quantity of the given dimension.
  void vector(std::string_view key, Vec3& value, units::Dimension dimension, Presence presence);
  void vector(std::string_view key, std::optional<Vec3>& value, units::Dimension dimension,
              Presence presence);

  // A nested map read by T's schema.
  template <class T>
  void section(std::string_view key, T& value, Presence presence) {
    if (const Entry* e = find(key, presence)) {
      read(doc_, map_node(*e), path_of(key), value, overlay_);
    }
  }

  // An optional nested map: present once given (or once the base had it).
  template <class T>
  void section(std::string_view key, std::optional<T>& value, Presence presence) {
    if (const Entry* e = find(key, presence)) {
      if (!value) value.emplace();
      read(doc_, map_node(*e), path_of(key), *value, overlay_);
    }
  }

  // A nested map given either by T's keys or by Alternative's, which converts to T.
  template <class T, class Alternative>
  void section_either(std::string_view key, T& value, Presence presence,
                      std::type_identity<Alternative>) {
    const Entry* e = find(key, presence);
    if (!e) return;
    const YAML::Node& node = map_node(*e);
    Alternative alternative{};
    const std::vector<std::string_view> own_keys = keys_of(value);
    const std::vector<std::string_view> other_keys = keys_of(alternative);
    const bool own = has_any(node, own_keys);
    if (has_any(node, other_keys)) {
      if (own) {
        fail(*e, key,
             "give either {" + join(own_keys) + "} or {" + join(other_keys) + "}, not a mix");
      }
      read(doc_, node, path_of(key), alternative, false, own_keys);
      value = alternative.converted();
    } else {
      read(doc_, node, path_of(key), value, overlay_, other_keys);
    }
  }

  // A nested map whose `tag` key names the alternative (in the order of `names`) that reads
  // the other keys. Over a base (overlay), the tag may be omitted to keep the base's
  // alternative; naming another alternative replaces the whole map.
  template <class... Ts, std::size_t N>
  void variant(std::string_view key, std::variant<Ts...>& value, std::string_view tag,
               const std::array<std::string_view, N>& names, Presence presence) {
    static_assert(N == sizeof...(Ts), "one name per alternative");
    const Entry* e = find(key, presence);
    if (!e) return;
    Reader alternative(doc_, map_node(*e), path_of(key), overlay_);
    const std::size_t index = alternative.choose(tag, names, value.index());
    if (index != value.index()) {
      value = make_alternative<std::variant<Ts...>>(index, std::index_sequence_for<Ts...>{});
      alternative.overlay_ = false;
    }
    const std::array<std::string_view, 1> tag_key{tag};
    std::visit([&](auto& a) { alternative.read_into(a, tag_key); }, value);
  }

  // A list of maps, each read by T's schema; items are named in key paths by their `name`
  // (which must be unique) or else by index.
  template <class T>
  void list(std::string_view key, std::vector<T>& items, Presence presence) {
    const Entry* e = find(key, presence);
    if (!e) return;
    const YAML::Node& list = list_node(*e, "a list");
    items.clear();
    std::map<std::string, std::string> names;  // name -> where first given
    std::size_t index = 0;
    for (const YAML::Node& node : list) {
      const std::string path = path_of(key) + "." + item_label(node, index++);
      claim_name(node, path, names);
      T item{};
      read(doc_, node, path, item);
      items.push_back(std::move(item));
    }
  }

  // A case's `materials:` map, NAME -> material with an optional `base:` (case_materials.hpp).
  void materials(std::string_view key, std::map<std::string, materials::Material>& values);

  // A condition on values read so far; reported at `key` (or at this map if key is absent).
  void check(bool ok, std::string_view key, std::string_view message) const;

 private:
  struct Entry {
    YAML::Node key;
    YAML::Node value;
    std::string name;
  };

  Reader(const Document& doc, const YAML::Node& map, std::string path, bool overlay);

  template <class T>
  void read_into(T& target, std::span<const std::string_view> extra_keys) {
    std::vector<std::string_view> known = keys_of(target);
    known.insert(known.end(), extra_keys.begin(), extra_keys.end());
    reject_unknown(known);
    fields(*this, target);
  }

  template <class K, class V, class KeyCodec, class ValueCodec>
  void read_table(std::string_view key, std::map<K, V>& values, const KeyCodec& key_codec,
                  const ValueCodec& value_codec) {
    const Entry* e = find(key, kOptional);
    if (!e) return;
    const Reader entries(doc_, map_node(*e), path_of(key), false);
    for (const Entry& entry : entries.entries_) {
      K k{};
      entries.parse_with(key_codec, entry.key, k, entry.name);
      V v{};
      entries.parse_with(value_codec, entries.scalar_node(entry, value_codec.expected()), v,
                         entry.name);
      values[k] = v;
    }
  }

  template <class Codec, class T>
  void parse_with(const Codec& codec, const YAML::Node& node, T& value,
                  std::string_view key) const {
    try {
      codec.parse(node.Scalar(), value);
    } catch (const BadValue& bad) {
      fail(node, key, bad.what());
    }
  }

  // The entry for `key`, or null when absent; InputError if required (and not an overlay).
  const Entry* find(std::string_view key, Presence presence) const;
  [[noreturn]] void missing(std::string_view key, const std::string& hint) const;
  void reject_unknown(std::span<const std::string_view> known) const;
  std::size_t choose(std::string_view tag, std::span<const std::string_view> names,
                     std::size_t current) const;
  void claim_name(const YAML::Node& item, const std::string& path,
                  std::map<std::string, std::string>& names) const;
  static bool has_any(const YAML::Node& map, std::span<const std::string_view> keys);

  const YAML::Node& scalar_node(const Entry& e, const std::string& expected) const;
  const YAML::Node& list_node(const Entry& e, const std::string& expected) const;
  const YAML::Node& map_node(const Entry& e) const;
  double to_quantity(const YAML::Node& node, const std::string& where, std::string_view key,
                     units::Dimension dimension, const Range& range,
                     std::string_view component) const;
  Vec3 to_vector(const Entry& e, std::string_view key, units::Dimension dimension) const;

  std::string path_of(std::string_view key) const;
  std::string where_value(const Entry& e) const;
  [[noreturn]] void fail(const Entry& e, std::string_view key, const std::string& message) const;
  [[noreturn]] void fail(const YAML::Node& node, std::string_view key,
                         const std::string& message) const;

  const Document& doc_;
  YAML::Node map_;
  std::string path_;
  bool overlay_;
  std::vector<Entry> entries_;
};

}  // namespace coldspray::case_file
