// A YAML tree together with where its nodes came from, so that every error can name
// "FILE:LINE:COLUMN" (or "--set KEY" for a value given on the command line).
#pragma once

#include <yaml-cpp/yaml.h>

#include <cstddef>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <tuple>
#include <unordered_map>
#include <utility>
#include <vector>

namespace coldspray::case_file {

class Document {
 public:
  // Reads a YAML file; InputError when it is missing, not a regular file, unreadable or not
  // valid YAML.
  static Document from_file(const std::string& path);
  // Parses YAML text; `name` stands for the file in messages (e.g. "builtin:al-ptw").
  static Document from_text(std::string name, std::string_view text);

  const std::string& name() const { return name_; }
  const YAML::Node& root() const { return root_; }
  // (The tree may then change: the origins' index is made again when next needed.)
  YAML::Node& root() {
    index_.clear();
    return root_;
  }

  // Records that `node` and everything under it came from `origin` (e.g. "--set solver.cfl").
  void mark_origin(const YAML::Node& node, std::string origin);
  // The same for the node at a key path (list items selected by name or index); false, marking
  // nothing, when there is no node there.
  bool mark_origin(std::span<const std::string> path, std::string origin);

  // "FILE:LINE:COLUMN" of a node (1-based), its origin if marked, or FILE for a node with no
  // position.
  std::string where(const YAML::Node& node) const;
  // The location of a map entry: the key's position, or the value's origin if marked.
  std::string where(const YAML::Node& key, const YAML::Node& value) const;
  // The location of the node at a key path (list items selected by name or index), or of its
  // deepest existing ancestor.
  std::string where(std::span<const std::string> path) const;

 private:
  Document(std::string name, YAML::Node root) : name_(std::move(name)), root_(std::move(root)) {}
  // Where a node came from: the latest origin whose tree holds it, or for a vector of the file,
  // the origin of a component set into it.
  std::optional<std::string> origin(const YAML::Node& node) const;
  std::optional<std::string> origin_holding(const YAML::Node& node) const;

  // The node at a key path, or its deepest existing ancestor (found = false), with the map key
  // that names it (none for the root and for list items).
  struct Located {
    std::optional<YAML::Node> key;
    YAML::Node node;
    bool found = true;
  };
  Located locate(std::span<const std::string> path) const;

  // The origins whose trees hold a node at each position in the text (a node has one position,
  // nodes of other texts, --set values, may share it): the candidates origin() checks, latest
  // last. A generated case marks an origin or more per body (`coldspray deposit`: 5 per
  // particle), and checking every origin's tree for each of the case's nodes took 20 s for 1000
  // particles, growing as their square. Made when first needed after the tree or its origins
  // change.
  using Position = std::tuple<int, int, int>;  // YAML::Mark's pos, line, column
  struct PositionHash {
    std::size_t operator()(const Position& p) const;
  };
  static Position position_of(const YAML::Node& node);
  const std::unordered_map<Position, std::vector<std::size_t>, PositionHash>& index() const;

  std::string name_;
  YAML::Node root_;
  std::vector<std::pair<YAML::Node, std::string>> origins_;
  mutable std::unordered_map<Position, std::vector<std::size_t>, PositionHash> index_;
};

// The index of the item of a list that `selector` names: the item whose `name` is selector, or
// the item at that integer index.
std::optional<std::size_t> find_item(const YAML::Node& list, std::string_view selector);

// How a key path names a list item: by its `name` when it has one, else by its index.
std::string item_label(const YAML::Node& item, std::size_t index);

// InputError located at the node of the key path (or its deepest existing ancestor), naming the
// dotted key path.
[[noreturn]] void fail_at(const Document& doc, const std::vector<std::string>& path,
                          const std::string& message);

// "a map", "a list", "nothing", "text 'abc'": for "expected X, got Y" messages.
std::string describe(const YAML::Node& node);

}  // namespace coldspray::case_file
