#include "case/writer.hpp"

#include "case/material_schema.hpp"
#include "case/shortest_number.hpp"

namespace coldspray::case_file {

void Writer::quantity(std::string_view key, double& value, units::Dimension dimension, Presence,
                      const Range&) {
  begin(key);
  out_ << shortest_text(value);
  unit_comment(dimension);
}

void Writer::quantity(std::string_view key, std::optional<double>& value,
                      units::Dimension dimension, Presence presence, const Range& range) {
  if (value) quantity(key, *value, dimension, presence, range);
}

void Writer::vector(std::string_view key, Vec3& value, units::Dimension dimension, Presence) {
  begin(key);
  out_ << YAML::Flow << YAML::BeginSeq;
  for (const double x : value) out_ << shortest_text(x);
  out_ << YAML::EndSeq;
  unit_comment(dimension);
}

void Writer::vector(std::string_view key, std::optional<Vec3>& value, units::Dimension dimension,
                    Presence presence) {
  if (value) vector(key, *value, dimension, presence);
}

void Writer::materials(std::string_view key, std::map<std::string, materials::Material>& values) {
  begin(key);
  if (values.empty()) out_ << YAML::Flow;
  out_ << YAML::BeginMap;
  for (auto& [name, material] : values) {
    out_ << YAML::Key << name << YAML::Value << YAML::BeginMap;
    fields(*this, material);
    out_ << YAML::EndMap;
  }
  out_ << YAML::EndMap;
}

void Writer::unit_comment(units::Dimension dimension) {
  if (dimension != units::kDimensionless) out_ << YAML::Comment(units::si_unit(dimension));
}

}  // namespace coldspray::case_file
