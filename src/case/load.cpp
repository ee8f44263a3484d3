#include "case/load.hpp"

#include <yaml-cpp/yaml.h>

#include <ostream>

#include "case/case_materials.hpp"
#include "case/case_schema.hpp"
#include "case/document.hpp"
#include "case/overrides.hpp"
#include "case/reader.hpp"
#include "case/validate.hpp"
#include "case/writer.hpp"

namespace coldspray::case_file {

Case load_case(const std::string& path, const std::vector<Override>& overrides) {
  Document doc = Document::from_file(path);
  for (const Override& o : overrides) apply_override(doc, o);
  Case c;
  Reader::read(doc, doc.root(), "", c);
  c.source_file = path;
  resolve_body_materials(doc, c);
  check_consistency(doc, c);
  return c;
}

void write_resolved(const Case& c, std::ostream& out) {
  Case copy = c;  // the schema functions take mutable references, for the Reader's sake
  YAML::Emitter emitter;
  std::string header = "The resolved case '" + c.name + "'";
  if (!c.source_file.empty()) header += " (from " + c.source_file + ")";
  emitter << YAML::Comment(header + ": every default filled in, every value in SI units.");
  emitter << YAML::BeginMap;
  Writer writer(emitter);
  fields(writer, copy);
  emitter << YAML::EndMap;
  out << emitter.c_str() << '\n';
}

}  // namespace coldspray::case_file
