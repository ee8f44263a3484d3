#include "case/moved_keys.hpp"

#include <array>
#include <functional>
#include <map>
#include <utility>
#include <vector>

#include "core/error.hpp"

namespace coldspray::case_file {

namespace {

constexpr std::array<std::pair<std::string_view, std::string_view>, 17> kMoved{{
    {"contact.model", "contact.peridynamics.model"},
    {"contact.beta", "contact.peridynamics.beta"},
    {"contact.r0", "contact.peridynamics.r0"},
    {"contact.cutoff", "contact.peridynamics.cutoff"},
    {"contact.alpha", "contact.peridynamics.alpha"},
    {"contact.repulsion_exponent", "contact.peridynamics.repulsion_exponent"},
    {"contact.attraction_exponent", "contact.peridynamics.attraction_exponent"},
    {"contact.fracture_energy", "contact.peridynamics.fracture_energy"},
    {"contact.yield_stretch", "contact.peridynamics.yield_stretch"},
    {"contact.softening", "contact.peridynamics.softening"},
    {"peridynamics.contact_distance", "contact.peridynamics.repulsion.distance"},
    {"peridynamics.contact_initial_fraction", "contact.peridynamics.repulsion.initial_fraction"},
    {"peridynamics.contact_stiffness", "contact.peridynamics.repulsion.stiffness"},
    {"contact.normal", "contact.mpm.normal"},
    {"contact.other_pairs_normal", "contact.mpm.other_pairs_normal"},
    {"contact.friction", "contact.mpm.friction"},
    {"contact.gap_check", "contact.mpm.gap_check"},
}};

std::vector<std::string> split(std::string_view path) {
  std::vector<std::string> out;
  for (std::size_t start = 0;;) {
    const std::size_t dot = path.find('.', start);
    out.emplace_back(path.substr(start, dot - start));
    if (dot == std::string_view::npos) return out;
    start = dot + 1;
  }
}

// The map holding the last segment of `path` (under the section that holds its first), walking
// maps only; an invalid node if there is none (or, with `make`, after making the maps that are
// missing).
YAML::Node parent_map(YAML::Node section, const std::vector<std::string>& path, bool make) {
  YAML::Node node = section;
  for (std::size_t i = 1; i + 1 < path.size(); ++i) {
    if (!node.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
    if (!node[path[i]] && !make) return YAML::Node(YAML::NodeType::Undefined);
    YAML::Node next = node[path[i]];
    if (make && (!next.IsDefined() || next.IsNull())) next = YAML::Node(YAML::NodeType::Map);
    if (make) node[path[i]] = next;
    node.reset(next);
  }
  return node.IsMap() ? node : YAML::Node(YAML::NodeType::Undefined);
}

// The root's sections that old keys move from or to, found in one pass over the root: a lookup
// by key walks the whole map, and a case may have very many keys (tests/case/input_guards_test).
std::map<std::string, YAML::Node, std::less<>> sections_of(const YAML::Node& root) {
  std::map<std::string, YAML::Node, std::less<>> sections;
  for (const auto& entry : root)
    if (entry.first.IsScalar() &&
        (entry.first.Scalar() == "contact" || entry.first.Scalar() == "peridynamics"))
      sections.emplace(entry.first.Scalar(), entry.second);
  return sections;
}

}  // namespace

std::optional<std::string> moved_key(std::string_view path) {
  for (const auto& [from, to] : kMoved)
    if (path == from || (path.starts_with(from) && path[from.size()] == '.'))
      return std::string(to) + std::string(path.substr(from.size()));
  return std::nullopt;
}

void move_old_keys(Document& doc) {
  YAML::Node root = doc.root();
  if (!root.IsMap()) return;  // the reader names what it is
  auto sections = sections_of(root);
  for (const auto& [from, to] : kMoved) {
    const std::vector<std::string> old_path = split(from), new_path = split(to);
    const auto old_section = sections.find(old_path.front());
    if (old_section == sections.end()) continue;
    YAML::Node old_parent = parent_map(old_section->second, old_path, false);
    if (!old_parent.IsDefined() || !old_parent[old_path.back()]) continue;
    const YAML::Node value = old_parent[old_path.back()];
    auto new_section = sections.find(new_path.front());
    if (new_section == sections.end() || new_section->second.IsNull()) {
      root[new_path.front()] = YAML::Node(YAML::NodeType::Map);
      new_section = sections.insert_or_assign(new_path.front(), root[new_path.front()]).first;
    }
    if (const YAML::Node np = parent_map(new_section->second, new_path, false);
        np.IsDefined() && np[new_path.back()])
      throw InputError(doc.where(old_path), std::string(from),
                       "gives " + std::string(to) + " a second time: " + std::string(from) +
                           " is its old name; keep one");
    YAML::Node new_parent = parent_map(new_section->second, new_path, true);
    if (!new_parent.IsDefined()) continue;  // not a map on the way: the reader names it
    new_parent[new_path.back()] = value;
    old_parent.remove(old_path.back());
  }
}

}  // namespace coldspray::case_file
