#include "case/overrides.hpp"

#include <cctype>
#include <vector>

#include "case/moved_keys.hpp"
#include "case/plain_yaml.hpp"
#include "core/error.hpp"
#include "core/text.hpp"

namespace coldspray::case_file {

namespace {

std::vector<std::string> split_path(const Override& o) {
  std::vector<std::string> segments;
  std::size_t start = 0;
  while (true) {
    const std::size_t dot = o.key.find('.', start);
    segments.push_back(o.key.substr(start, dot - start));
    if (segments.back().empty()) {
      throw InputError("--set " + o.key, o.key, "empty name in the key path (KEY is like a.b.c)");
    }
    if (dot == std::string::npos) return segments;
    if (segments.size() == static_cast<std::size_t>(kMaxNesting)) {
      throw InputError(
          "--set " + o.key, o.key,
          "a key path of more than " + std::to_string(kMaxNesting) + " names is not accepted");
    }
    start = dot + 1;
  }
}

YAML::Node parse_value(const Override& o) {
  return load_plain_yaml(o.value, {"--set " + o.key, o.key});
}

std::string item_names(const YAML::Node& list) {
  std::string out;
  for (std::size_t i = 0; i < list.size(); ++i) {
    out += (out.empty() ? "" : ", ") + item_label(list[i], i);
  }
  return out;
}

}  // namespace

Override parse_override(std::string_view text) {
  const std::size_t eq = text.find('=');
  if (eq == std::string_view::npos) {
    throw InputError("--set", "", "expected KEY=VALUE, got '" + std::string(text) + "'");
  }
  const std::string key(trim(text.substr(0, eq)));
  const std::string value(trim(text.substr(eq + 1)));
  if (key.empty()) {
    throw InputError("--set", "", "no KEY before '=' in '" + std::string(text) + "'");
  }
  if (value.empty()) {
    throw InputError("--set " + key, key, "no VALUE after '=' (write KEY=VALUE)");
  }
  return {key, value};
}

void apply_override(Document& doc, const Override& given) {
  const std::string origin = "--set " + given.key;
  // A key that moved sets its new place (case/moved_keys.hpp).
  const Override o{moved_key(given.key).value_or(given.key), given.value};
  const std::vector<std::string> segments = split_path(o);
  const YAML::Node value = parse_value(o);
  YAML::Node node = doc.root();
  std::string walked;
  for (std::size_t i = 0; i < segments.size(); ++i) {
    const std::string& segment = segments[i];
    const bool last = i + 1 == segments.size();
    const std::string path = walked.empty() ? segment : walked + "." + segment;
    if (node.IsSequence()) {
      const auto index = find_item(node, segment);
      if (!index) {
        throw InputError(origin, path,
                         "no item '" + segment + "' in the list '" + walked +
                             "' (items: " + item_names(node) + "; or an index from 0)");
      }
      if (last) {
        node[*index] = value;
      } else {
        const YAML::Node child = node[*index];
        node.reset(child);
      }
    } else if (node.IsMap() || node.IsNull()) {
      if (last) {
        node[segment] = value;
      } else if (const YAML::Node existing = node[segment]; existing.IsDefined()) {
        node.reset(existing);
      } else {
        const YAML::Node created(YAML::NodeType::Map);
        node[segment] = created;
        doc.mark_origin(created, origin);
        node.reset(created);
      }
    } else {
      throw InputError(origin, path,
                       "'" + walked + "' is a single value, it has no key '" + segment + "'");
    }
    walked = path;
  }
  doc.mark_origin(value, origin);
}

}  // namespace coldspray::case_file
