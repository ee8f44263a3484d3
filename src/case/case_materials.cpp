#include "case/case_materials.hpp"

#include <algorithm>
#include <optional>
#include <vector>

#include "case/load.hpp"
#include "case/material_schema.hpp"
#include "case/reader.hpp"
#include "case/suggest.hpp"
#include "core/error.hpp"

namespace coldspray::case_file {

namespace {

constexpr std::array<std::string_view, 1> kBaseKey{"base"};

bool is_builtin(const std::string& name) {
  const std::vector<std::string> names = builtin_material_names();
  return std::find(names.begin(), names.end(), name) != names.end();
}

// Every material name a case may use: its own, then the built-ins.
std::vector<std::string> known_materials(std::vector<std::string> own) {
  for (std::string& name : builtin_material_names()) own.push_back(std::move(name));
  return own;
}

materials::Material base_material(const Document& doc, const YAML::Node& base,
                                  const std::string& path) {
  if (!base.IsScalar()) {
    throw InputError(doc.where(base), path + ".base",
                     "expected the name of a built-in material, got " + describe(base));
  }
  if (!is_builtin(base.Scalar())) {
    throw InputError(doc.where(base), path + ".base",
                     unknown_word("built-in material", base.Scalar(), builtin_material_names()));
  }
  return builtin_material(base.Scalar());
}

// Whether a group, as a case gives it over a base, keeps some of the base's values: a map that
// neither names another model nor switches to the other elastic form.
bool keeps_base_values(std::string_view group, const YAML::Node& value,
                       const materials::Material& m, const materials::Material& base) {
  if (!value.IsMap()) return false;
  if (group == "strength") return m.strength.index() == base.strength.index();
  if (group == "shear_modulus_model") return m.shear_modulus.index() == base.shear_modulus.index();
  if (group == "melt") return m.melt.index() == base.melt.index();
  if (group == "eos") return m.eos.index() == base.eos.index();
  return !value["youngs_modulus"] && !value["poisson_ratio"];  // elastic
}

// Gives every group a source: a group set here without one gets the file's name (followed by
// the base's source when it keeps base values), a group left at its default gets "default".
void attribute_sources(const Document& doc, const YAML::Node& node, const std::string& name,
                       const std::optional<materials::Material>& base, materials::Material& m) {
  const YAML::Node own_sources = node["sources"];
  for (std::string_view group_view : kMaterialGroups) {
    const std::string group(group_view);
    if (own_sources && own_sources[group]) continue;
    if (!node[group]) {
      if (!m.sources.contains(group)) m.sources[group] = "default";
      continue;
    }
    std::string source = doc.name() + ", material '" + name + "'";
    if (base && base->sources.contains(group) && keeps_base_values(group, node[group], m, *base)) {
      source += ", over " + base->name + ": " + base->sources.at(group);
    }
    m.sources[group] = source;
  }
}

}  // namespace

materials::Material read_material(const Document& doc, const YAML::Node& node,
                                  const std::string& path, const std::string& name) {
  std::optional<materials::Material> base;
  if (node.IsMap() && node["base"]) base = base_material(doc, node["base"], path);
  materials::Material m = base.value_or(materials::Material{});
  Reader::read(doc, node, path, m, base.has_value(), kBaseKey);
  m.name = name;
  attribute_sources(doc, node, name, base, m);
  return m;
}

void resolve_body_materials(const Document& doc, Case& c) {
  std::map<std::string, materials::Material> used;
  for (const Body& b : c.bodies) {
    if (const auto own = c.materials.find(b.material); own != c.materials.end()) {
      used[b.material] = own->second;
    } else if (is_builtin(b.material)) {
      used[b.material] = builtin_material(b.material);
    } else {
      std::vector<std::string> defined;
      for (const auto& [name, material] : c.materials) defined.push_back(name);
      const std::array<std::string, 3> path{"bodies", b.name, "material"};
      throw InputError(doc.where(path), "bodies." + b.name + ".material",
                       unknown_word("material", b.material, known_materials(defined)));
    }
  }
  c.materials = std::move(used);
}

materials::Material resolve_material(const std::string& reference, const std::string& where) {
  const std::size_t colon = reference.rfind(':');
  if (colon == std::string::npos) return builtin_material(reference, where);
  const std::string name = reference.substr(colon + 1);
  const Document doc = Document::from_file(reference.substr(0, colon));
  const YAML::Node& root = doc.root();
  const YAML::Node defined = root.IsMap() && root["materials"] ? root["materials"] : YAML::Node();
  if (defined.IsMap() && defined[name]) {
    return read_material(doc, defined[name], "materials." + name, name);
  }
  if (is_builtin(name)) return builtin_material(name);
  std::vector<std::string> own;
  if (defined.IsMap()) {
    for (const auto& entry : defined) own.push_back(entry.first.Scalar());
  }
  throw InputError(doc.name(), "materials." + name,
                   unknown_word("material", name, known_materials(own)));
}

}  // namespace coldspray::case_file
