#include "case/document.hpp"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <vector>

#include "case/plain_yaml.hpp"
#include "core/error.hpp"

namespace coldspray::case_file {

namespace {

// Calls `visit` on `tree` and every node under it, map keys included, until it returns true;
// returns whether it did. A loop over a stack, not a recursion: how deep a tree may be is
// plain_yaml's and the --set key paths' business, not the call stack's.
template <class Visit>
bool any_node(const YAML::Node& tree, Visit visit) {
  std::vector<YAML::Node> pending{tree};
  while (!pending.empty()) {
    const YAML::Node at = pending.back();
    pending.pop_back();
    if (visit(at)) return true;
    if (at.IsMap()) {
      for (const auto& entry : at) {
        pending.push_back(entry.first);
        pending.push_back(entry.second);
      }
    } else if (at.IsSequence()) {
      for (const auto& item : at) pending.push_back(item);
    }
  }
  return false;
}

// Whether `node` is `tree` or lies under it.
bool contains(const YAML::Node& tree, const YAML::Node& node) {
  return any_node(tree, [&](const YAML::Node& at) { return at.is(node); });
}

}  // namespace

Document Document::from_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path, "", "no such file");
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, "", "is a directory");
  // A device or a fifo is not a file to read to its end: /dev/zero and /dev/full never end (the
  // read below grew until std::bad_alloc, exit 1), and a fifo blocks until a writer comes.
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path, "", "is not a regular file (a device, a fifo or a socket)");
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open the file for reading");
  std::ostringstream text;
  text << in.rdbuf();
  return from_text(path, text.str());
}

Document Document::from_text(std::string name, std::string_view text) {
  YAML::Node root = load_plain_yaml(text, {name, ""});
  return Document(std::move(name), std::move(root));
}

void Document::mark_origin(const YAML::Node& node, std::string origin) {
  origins_.emplace_back(node, std::move(origin));
  index_.clear();
}

std::size_t Document::PositionHash::operator()(const Position& p) const {
  const auto [pos, line, column] = p;
  return std::hash<long long>{}((static_cast<long long>(pos) << 32) ^
                                (static_cast<long long>(line) << 16) ^ column);
}

Document::Position Document::position_of(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return {mark.pos, mark.line, mark.column};
}

const std::unordered_map<Document::Position, std::vector<std::size_t>, Document::PositionHash>&
Document::index() const {
  if (!index_.empty() || origins_.empty()) return index_;
  for (std::size_t k = 0; k < origins_.size(); ++k)
    any_node(origins_[k].first, [&](const YAML::Node& at) {
      std::vector<std::size_t>& holders = index_[position_of(at)];
      if (holders.empty() || holders.back() != k) holders.push_back(k);
      return false;
    });
  return index_;
}

std::optional<std::string> Document::origin_holding(const YAML::Node& node) const {
  // A tree that holds the node holds a node at its position: only those origins can. Latest
  // first: a later --set may have replaced part of what an earlier one created.
  const auto& by_position = index();
  const auto found = by_position.find(position_of(node));
  if (found == by_position.end()) return std::nullopt;
  for (auto k = found->second.rbegin(); k != found->second.rend(); ++k) {
    if (contains(origins_[*k].first, node)) return origins_[*k].second;
  }
  return std::nullopt;
}

std::optional<std::string> Document::origin(const YAML::Node& node) const {
  if (auto held = origin_holding(node)) return held;
  // A vector of the file with a component set on the command line (--set
  // bodies.particle.velocity.0=...): a problem with the vector is the --set's. The file's line
  // does not hold the value at fault; the fuzzer found velocity, center and max reported there.
  if (node.IsSequence()) {
    for (const auto& item : node)
      if (item.IsScalar())
        if (auto set = origin_holding(item)) return set;
  }
  return std::nullopt;
}

std::string Document::where(const YAML::Node& node) const {
  if (auto o = origin(node)) return *o;
  const YAML::Mark mark = node.Mark();
  if (mark.is_null()) return name_;
  return name_ + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

std::string Document::where(const YAML::Node& key, const YAML::Node& value) const {
  if (auto o = origin(value)) return *o;
  return key.Mark().is_null() ? where(value) : where(key);
}

Document::Located Document::locate(std::span<const std::string> path) const {
  Located at{std::nullopt, root_};
  for (const std::string& segment : path) {
    const YAML::Node parent = at.node;
    bool found = false;
    if (parent.IsMap()) {
      for (const auto& entry : parent) {
        if (entry.first.IsScalar() && entry.first.Scalar() == segment) {
          at.key.emplace(entry.first);
          at.node.reset(entry.second);
          found = true;
        }
      }
    } else if (parent.IsSequence()) {
      if (const auto index = find_item(parent, segment)) {
        at.key.reset();
        at.node.reset(parent[*index]);
        found = true;
      }
    }
    if (!found) {
      at.found = false;
      break;
    }
  }
  return at;
}

std::string Document::where(std::span<const std::string> path) const {
  const Located at = locate(path);
  if (at.node.IsNull() && at.key) return where(*at.key, at.node);
  return where(at.node);
}

bool Document::mark_origin(std::span<const std::string> path, std::string origin) {
  const Located at = locate(path);
  if (!at.found) return false;
  mark_origin(at.node, std::move(origin));
  return true;
}

std::optional<std::size_t> find_item(const YAML::Node& list, std::string_view selector) {
  for (std::size_t i = 0; i < list.size(); ++i) {
    const YAML::Node item = list[i];
    if (item.IsMap() && item["name"] && item["name"].IsScalar() &&
        item["name"].Scalar() == selector) {
      return i;
    }
  }
  std::size_t index = 0;
  const auto [end, ec] = std::from_chars(selector.data(), selector.data() + selector.size(), index);
  if (ec == std::errc() && end == selector.data() + selector.size() && index < list.size()) {
    return index;
  }
  return std::nullopt;
}

std::string item_label(const YAML::Node& item, std::size_t index) {
  if (item.IsMap() && item["name"] && item["name"].IsScalar() && !item["name"].Scalar().empty()) {
    return item["name"].Scalar();
  }
  return std::to_string(index);
}

void fail_at(const Document& doc, const std::vector<std::string>& path,
             const std::string& message) {
  std::string key;
  for (const std::string& segment : path) key += (key.empty() ? "" : ".") + segment;
  throw InputError(doc.where(path), key, message);
}

std::string describe(const YAML::Node& node) {
  switch (node.Type()) {
    case YAML::NodeType::Map:
      return "a map";
    case YAML::NodeType::Sequence:
      return "a list";
    case YAML::NodeType::Scalar:
      return "text '" + node.Scalar() + "'";
    default:
      return "nothing";
  }
}

}  // namespace coldspray::case_file
