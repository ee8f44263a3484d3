#include "case/key_locations.hpp"

#include <utility>
#include <vector>

namespace coldspray::case_file {

std::map<std::string, std::string> key_locations(const Document& doc) {
  std::map<std::string, std::string> out;
  // A stack of (node, its key path): the walk is a loop, as deep as the document may be.
  std::vector<std::pair<YAML::Node, std::string>> pending{{doc.root(), ""}};
  auto child = [](const std::string& path, const std::string& name) {
    return path.empty() ? name : path + "." + name;
  };
  while (!pending.empty()) {
    const auto [node, path] = pending.back();
    pending.pop_back();
    if (node.IsMap()) {
      for (const auto& entry : node) {
        if (!entry.first.IsScalar()) continue;
        const std::string key = child(path, entry.first.Scalar());
        out[key] = doc.where(entry.first, entry.second);
        pending.emplace_back(entry.second, key);
      }
    } else if (node.IsSequence()) {
      for (std::size_t i = 0; i < node.size(); ++i) {
        const YAML::Node item = node[i];
        const std::string key = child(path, item_label(item, i));
        out[key] = doc.where(item);
        pending.emplace_back(item, key);
      }
    }
  }
  return out;
}

}  // namespace coldspray::case_file
