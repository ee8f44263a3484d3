#include <vector>

#include "case/case_materials.hpp"
#include "case/load.hpp"
#include "case/suggest.hpp"
#include "core/error.hpp"
#include "materials/database.hpp"

namespace coldspray::case_file {

std::vector<std::string> builtin_material_names() {
  std::vector<std::string> names;
  for (const auto& [name, text] : materials::builtin_sources()) names.push_back(name);
  return names;
}

materials::Material builtin_material(const std::string& name, const std::string& where) {
  const auto& sources = materials::builtin_sources();
  const auto it = sources.find(name);
  if (it == sources.end()) {
    throw InputError(where, "", unknown_word("built-in material", name, builtin_material_names()));
  }
  const Document doc = Document::from_text("builtin:" + name, it->second);
  return read_material(doc, doc.root(), "", name);
}

}  // namespace coldspray::case_file
