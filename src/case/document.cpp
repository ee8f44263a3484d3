#include "case/document.hpp"

#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/error.hpp"

namespace coldspray::case_file {

namespace {

bool contains(const YAML::Node& tree, const YAML::Node& node) {
  if (tree.is(node)) return true;
  if (tree.IsMap()) {
    for (const auto& entry : tree) {
      if (contains(entry.first, node) || contains(entry.second, node)) return true;
    }
  } else if (tree.IsSequence()) {
    for (const auto& item : tree) {
      if (contains(item, node)) return true;
    }
  }
  return false;
}

YAML::Node parse(const std::string& name, std::istream& in) {
  try {
    return YAML::Load(in);
  } catch (const YAML::ParserException& e) {
    throw InputError(
        name + ":" + std::to_string(e.mark.line + 1) + ":" + std::to_string(e.mark.column + 1), "",
        "invalid YAML: " + e.msg);
  }
}

}  // namespace

Document Document::from_file(const std::string& path) {
  std::error_code ec;
  if (!std::filesystem::exists(path, ec)) throw InputError(path, "", "no such file");
  if (std::filesystem::is_directory(path, ec)) throw InputError(path, "", "is a directory");
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open the file for reading");
  return Document(path, parse(path, in));
}

Document Document::from_text(std::string name, std::string_view text) {
  std::istringstream in{std::string(text)};
  YAML::Node root = parse(name, in);
  return Document(std::move(name), std::move(root));
}

void Document::mark_origin(const YAML::Node& node, std::string origin) {
  origins_.emplace_back(node, std::move(origin));
}

std::optional<std::string> Document::origin(const YAML::Node& node) const {
  // Latest first: a later --set may have replaced part of what an earlier one created.
  for (auto it = origins_.rbegin(); it != origins_.rend(); ++it) {
    if (contains(it->first, node)) return it->second;
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
