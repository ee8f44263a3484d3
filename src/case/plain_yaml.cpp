#include "case/plain_yaml.hpp"

#include <yaml-cpp/eventhandler.h>

#include <sstream>

#include "core/error.hpp"

namespace coldspray::case_file {

namespace {

// A problem found in the text, with its position.
struct Refused {
  YAML::Mark mark;
  std::string message;
};

// Walks the parser's events (linear in the text: an alias is one event, not the tree it names)
// and stops at the first anchor, alias or nesting too deep.
class PlainTreeCheck : public YAML::EventHandler {
 public:
  void OnDocumentStart(const YAML::Mark&) override {}
  void OnDocumentEnd() override {}
  void OnNull(const YAML::Mark& mark, YAML::anchor_t anchor) override {
    refuse_anchor(mark, anchor);
  }
  void OnAlias(const YAML::Mark& mark, YAML::anchor_t) override {
    throw Refused{mark,
                  "YAML aliases (*NAME) are not accepted: write the value out where it is used"};
  }
  void OnScalar(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                const std::string&) override {
    refuse_anchor(mark, anchor);
  }
  void OnSequenceStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                       YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnSequenceEnd() override { --depth_; }
  void OnMapStart(const YAML::Mark& mark, const std::string&, YAML::anchor_t anchor,
                  YAML::EmitterStyle::value) override {
    open(mark, anchor);
  }
  void OnMapEnd() override { --depth_; }

 private:
  static void refuse_anchor(const YAML::Mark& mark, YAML::anchor_t anchor) {
    if (anchor != YAML::NullAnchor)
      throw Refused{mark,
                    "YAML anchors (&NAME) are not accepted: write the value out where it is used"};
  }
  void open(const YAML::Mark& mark, YAML::anchor_t anchor) {
    refuse_anchor(mark, anchor);
    if (++depth_ > kMaxNesting)
      throw Refused{mark, "maps and lists nested more than " + std::to_string(kMaxNesting) +
                              " deep are not accepted"};
  }

  int depth_ = 0;
};

std::string where(const YamlSource& source, const YAML::Mark& mark) {
  if (!source.key.empty()) return source.name;
  return source.name + ":" + std::to_string(mark.line + 1) + ":" + std::to_string(mark.column + 1);
}

}  // namespace

YAML::Node load_plain_yaml(std::string_view text, const YamlSource& source) {
  const std::string invalid =
      source.key.empty() ? "invalid YAML: " : "invalid YAML value '" + std::string(text) + "': ";
  try {
    std::istringstream events{std::string(text)};
    YAML::Parser parser(events);
    PlainTreeCheck check;
    parser.HandleNextDocument(check);
    return YAML::Load(std::string(text));
  } catch (const Refused& r) {
    throw InputError(where(source, r.mark), source.key, r.message);
  } catch (const YAML::ParserException& e) {
    throw InputError(where(source, e.mark), source.key, invalid + e.msg);
  }
}

}  // namespace coldspray::case_file
