#include "case/load.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <ostream>
#include <stdexcept>
#include <utility>

#include "case/case_materials.hpp"
#include "case/case_schema.hpp"
#include "case/document.hpp"
#include "case/key_locations.hpp"
#include "case/moved_keys.hpp"
#include "case/overrides.hpp"
#include "case/reader.hpp"
#include "case/size_limits.hpp"
#include "case/validate.hpp"
#include "case/writer.hpp"

namespace coldspray::case_file {

namespace {

Case read_case(Document& doc, const std::vector<Override>& overrides) {
  // Old keys move first, so that a --set of a key the file gives the old way replaces it; and
  // again after the --set values, for a map one gives with old keys in it.
  move_old_keys(doc);
  for (const Override& o : overrides) apply_override(doc, o);
  move_old_keys(doc);
  Case c;
  Reader::read(doc, doc.root(), "", c);
  c.source_file = doc.name();
  resolve_body_materials(doc, c);
  if (c.solver.method == Method::Peridynamics) {
    if (!c.peridynamics) c.peridynamics.emplace();
    // PD's own default time-step fraction, when the case gives none (docs/pd.md, "Time step").
    const YAML::Node& root = std::as_const(doc).root();
    if (!(root["solver"] && root["solver"]["cfl"])) c.solver.cfl = kPeridynamicsCfl;
  }
  // Three or more bodies meet where two of them meet a third: the contact normal that does not
  // depend on the bodies' order is their default (docs/validation/multi-particle.md, "Contact
  // normals"); two bodies keep the thesis' MVG.
  const YAML::Node& contact = std::as_const(doc).root()["contact"];
  if (c.bodies.size() >= 3 && !(contact && contact["mpm"] && contact["mpm"]["normal"]))
    c.contact.mpm.normal = ContactNormal::AverageGradient;
  check_consistency(doc, c);
  check_size_limits(doc, c);
  c.key_locations = key_locations(doc);
  return c;
}

std::vector<std::string> split_key(const std::string& key) {
  std::vector<std::string> segments;
  std::size_t start = 0;
  while (start <= key.size() && !key.empty()) {
    const std::size_t dot = std::min(key.find('.', start), key.size());
    segments.push_back(key.substr(start, dot - start));
    start = dot + 1;
  }
  return segments;
}

}  // namespace

Case load_case(const std::string& path, const std::vector<Override>& overrides) {
  Document doc = Document::from_file(path);
  return read_case(doc, overrides);
}

Case load_case_text(const std::string& name, std::string_view text,
                    const std::vector<ValueOrigin>& origins,
                    const std::vector<Override>& overrides) {
  Document doc = Document::from_text(name, text);
  for (const ValueOrigin& o : origins) {
    // A generator that names a key it did not write is a bug, not bad input.
    if (!doc.mark_origin(split_key(o.key), o.origin))
      throw std::logic_error("load_case_text: no key '" + o.key + "' in " + name);
  }
  return read_case(doc, overrides);
}

Limits limits_of_overrides(const std::vector<Override>& overrides) {
  Document doc = Document::from_text("--set", "{}");
  for (const Override& o : overrides)
    if (o.key == "limits" || o.key.starts_with("limits.")) apply_override(doc, o);
  Limits limits;
  if (const YAML::Node node = std::as_const(doc).root()["limits"])
    Reader::read(doc, node, "limits", limits);
  return limits;
}

std::string apply_overrides(const std::string& name, std::string_view text,
                            const std::vector<Override>& overrides) {
  Document doc = Document::from_text(name, text);
  for (const Override& o : overrides) apply_override(doc, o);
  YAML::Emitter emitter;
  emitter << doc.root();
  return std::string(emitter.c_str()) + "\n";
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
