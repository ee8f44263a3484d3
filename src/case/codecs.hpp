// Codecs turn one YAML scalar into a value and back: the schema names one per text field.
// Each has expected() (for "expected ..., got ..." messages), parse(text, value) (throws
// BadValue) and format(value).
#pragma once

#include <algorithm>
#include <array>
#include <span>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>

#include "case/suggest.hpp"

namespace coldspray::case_file {

// A scalar that does not parse; the reader adds the location and key.
class BadValue : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Free text.
struct Text {
  std::string expected() const { return "text"; }
  void parse(std::string_view text, std::string& value) const { value = text; }
  std::string format(const std::string& value) const { return value; }
};

// true or false.
struct Flag {
  std::string expected() const { return "true or false"; }
  void parse(std::string_view text, bool& value) const;
  std::string format(bool value) const { return value ? "true" : "false"; }
};

// A whole number of at least `min`.
struct WholeNumber {
  int min = 0;

  std::string expected() const { return "a whole number >= " + std::to_string(min); }
  void parse(std::string_view text, int& value) const;
  std::string format(int value) const { return std::to_string(value); }
};

// Text restricted to a fixed set of words.
struct Keywords {
  std::span<const std::string_view> words;

  std::string expected() const { return "one of: " + join(words); }
  void parse(std::string_view text, std::string& value) const;
  std::string format(const std::string& value) const { return value; }
};

// An enumeration written by name.
template <class E, std::size_t N>
struct Names {
  std::array<std::pair<std::string_view, E>, N> entries;

  std::array<std::string_view, N> words() const {
    std::array<std::string_view, N> out;
    std::transform(entries.begin(), entries.end(), out.begin(),
                   [](const auto& e) { return e.first; });
    return out;
  }
  std::string expected() const { return "one of: " + join(words()); }
  void parse(std::string_view text, E& value) const {
    for (const auto& [name, e] : entries) {
      if (name == text) {
        value = e;
        return;
      }
    }
    throw BadValue(unknown_word("value", text, words()));
  }
  std::string format(const E& value) const {
    for (const auto& [name, e] : entries) {
      if (e == value) return std::string(name);
    }
    throw std::logic_error("enumerator without a name");
  }
};

}  // namespace coldspray::case_file
