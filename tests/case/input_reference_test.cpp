// docs/input-reference.md documents every key of the schema and every name a key accepts.
#include <gtest/gtest.h>

#include <fstream>
#include <optional>
#include <set>
#include <sstream>

#include "case/case_schema.hpp"
#include "case/load.hpp"
#include "case_test_support.hpp"

namespace coldspray::case_file {
namespace {

// Walks the whole schema, every alternative of every variant, and collects the keys and the
// names of choices.
class Vocabulary {
 public:
  template <class T, class Codec>
  void scalar(std::string_view key, T&, const Codec& codec, Presence) {
    add(key);
    add_words(codec);
  }
  template <class T, class Codec>
  void scalars(std::string_view key, std::vector<T>&, const Codec& codec, Presence) {
    add(key);
    add_words(codec);
  }
  template <class Map, class KeyCodec, class ValueCodec, class... Fill>
  void table(std::string_view key, Map&, const KeyCodec& key_codec, const ValueCodec& value_codec,
             const Fill&...) {
    add(key);
    add_words(key_codec);
    add_words(value_codec);
  }
  template <class... Args>
  void quantity(std::string_view key, Args&&...) {
    add(key);
  }
  template <class... Args>
  void vector(std::string_view key, Args&&...) {
    add(key);
  }
  template <class T>
  void section(std::string_view key, T& value, Presence) {
    add(key);
    fields(*this, value);
  }
  template <class T>
  void section(std::string_view key, std::optional<T>&, Presence presence) {
    T value{};
    section(key, value, presence);
  }
  template <class T, class Alternative>
  void section_either(std::string_view key, T& value, Presence presence,
                      std::type_identity<Alternative>) {
    section(key, value, presence);
    Alternative alternative{};
    fields(*this, alternative);
  }
  template <class... Ts, std::size_t N>
  void variant(std::string_view key, std::variant<Ts...>&, std::string_view tag,
               const std::array<std::string_view, N>& names, Presence) {
    add(key);
    add(tag);
    for (std::string_view name : names) add(name);
    (visit_alternative<Ts>(), ...);
  }
  template <class T>
  void list(std::string_view key, std::vector<T>&, Presence) {
    add(key);
    T item{};
    fields(*this, item);
  }
  void materials(std::string_view key, std::map<std::string, materials::Material>&) {
    add(key);
    materials::Material m;
    fields(*this, m);
  }
  template <class... Args>
  void check(Args&&...) {}

  const std::set<std::string>& words() const { return words_; }

 private:
  template <class T>
  void visit_alternative() {
    T alternative{};
    fields(*this, alternative);
  }
  template <class Codec>
  void add_words(const Codec& codec) {
    if constexpr (requires { codec.words(); }) {
      for (std::string_view w : codec.words()) add(w);
    } else if constexpr (requires { codec.words.size(); }) {
      for (std::string_view w : codec.words) add(w);
    }
  }
  void add(std::string_view word) { words_.emplace(word); }

  std::set<std::string> words_;
};

TEST(InputReference, DocumentsEveryKeyAndChoice) {
  std::ifstream in(std::string(COLDSPRAY_TEST_DATA) + "/../../docs/input-reference.md");
  ASSERT_TRUE(in) << "docs/input-reference.md not found";
  std::stringstream text;
  text << in.rdbuf();
  Vocabulary vocabulary;
  Case c;
  fields(vocabulary, c);
  EXPECT_GT(vocabulary.words().size(), 100u);
  for (const std::string& word : vocabulary.words()) {
    EXPECT_TRUE(testing::contains(text.str(), "`" + word + "`"));
  }
  for (const char* form :
       {"`max-gradient`", "`average-gradient`", "`highest-id`", "`body:NAME`", "`base`"}) {
    EXPECT_TRUE(testing::contains(text.str(), form));
  }
  // The built-in materials' table lists every data/materials/NAME.yaml.
  for (const std::string& name : builtin_material_names()) {
    EXPECT_TRUE(testing::contains(text.str(), "| `" + name + "` |")) << name;
  }
}

}  // namespace
}  // namespace coldspray::case_file
