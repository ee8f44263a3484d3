// Writes structs as YAML by their schema (the same `fields` functions the Reader runs): every
// field, defaults included, as plain SI numbers that read back to the same doubles.
#pragma once

#include <yaml-cpp/yaml.h>

#include <array>
#include <map>
#include <optional>
#include <string>
#include <string_view>
#include <type_traits>
#include <variant>
#include <vector>

#include "case/case.hpp"
#include "case/field_rules.hpp"
#include "core/units.hpp"
#include "materials/material.hpp"

namespace coldspray::case_file {

class Writer {
 public:
  explicit Writer(YAML::Emitter& out) : out_(out) {}

  template <class T, class Codec>
  void scalar(std::string_view key, T& value, const Codec& codec, Presence) {
    begin(key);
    out_ << codec.format(value);
  }

  template <class T, class Codec>
  void scalars(std::string_view key, std::vector<T>& values, const Codec& codec, Presence) {
    begin(key);
    out_ << YAML::Flow << YAML::BeginSeq;
    for (const T& v : values) out_ << codec.format(v);
    out_ << YAML::EndSeq;
  }

  template <class K, class V, class KeyCodec, class ValueCodec>
  void table(std::string_view key, std::map<K, V>& values, const KeyCodec& key_codec,
             const ValueCodec& value_codec) {
    begin(key);
    if (values.empty()) out_ << YAML::Flow;
    out_ << YAML::BeginMap;
    for (const auto& [k, v] : values) {
      out_ << YAML::Key << key_codec.format(k) << YAML::Value << value_codec.format(v);
    }
    out_ << YAML::EndMap;
  }

  template <class K, class V, class KeyCodec, class ValueCodec>
  void table(std::string_view key, std::map<K, V>& values, const KeyCodec& key_codec,
             const ValueCodec& value_codec, const V&) {
    table(key, values, key_codec, value_codec);
  }

  void quantity(std::string_view key, double& value, units::Dimension dimension, Presence,
                const Range& = kAnyValue);
  void quantity(std::string_view key, std::optional<double>& value, units::Dimension dimension,
                Presence presence, const Range& range = kAnyValue);

  void vector(std::string_view key, Vec3& value, units::Dimension dimension, Presence);
  void vector(std::string_view key, std::optional<Vec3>& value, units::Dimension dimension,
              Presence presence);

  template <class T>
  void section(std::string_view key, T& value, Presence) {
    begin(key);
    out_ << YAML::BeginMap;
    fields(*this, value);
    out_ << YAML::EndMap;
  }

  template <class T>
  void section(std::string_view key, std::optional<T>& value, Presence presence) {
    if (value) section(key, *value, presence);
  }

  // Always written in T's own form.
  template <class T, class Alternative>
  void section_either(std::string_view key, T& value, Presence presence,
                      std::type_identity<Alternative>) {
    section(key, value, presence);
  }

  template <class... Ts, std::size_t N>
  void variant(std::string_view key, std::variant<Ts...>& value, std::string_view tag,
               const std::array<std::string_view, N>& names, Presence) {
    begin(key);
    out_ << YAML::BeginMap;
    out_ << YAML::Key << std::string(tag) << YAML::Value << std::string(names[value.index()]);
    std::visit([&](auto& alternative) { fields(*this, alternative); }, value);
    out_ << YAML::EndMap;
  }

  template <class T>
  void list(std::string_view key, std::vector<T>& items, Presence) {
    begin(key);
    if (items.empty()) out_ << YAML::Flow;
    out_ << YAML::BeginSeq;
    for (T& item : items) {
      out_ << YAML::BeginMap;
      fields(*this, item);
      out_ << YAML::EndMap;
    }
    out_ << YAML::EndSeq;
  }

  void materials(std::string_view key, std::map<std::string, materials::Material>& values);

  // Conditions are the Reader's business.
  template <class... Args>
  void check(Args&&...) {}

 private:
  void begin(std::string_view key) { out_ << YAML::Key << std::string(key) << YAML::Value; }
  void unit_comment(units::Dimension dimension);

  YAML::Emitter& out_;
};

}  // namespace coldspray::case_file
