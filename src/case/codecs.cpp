#include "case/codecs.hpp"

#include <algorithm>

namespace coldspray::case_file {

void Flag::parse(std::string_view text, bool& value) const {
  if (text != "true" && text != "false") {
    throw BadValue("expected true or false, got '" + std::string(text) + "'");
  }
  value = text == "true";
}

void WholeNumber::parse(std::string_view text, int& value) const {
  std::size_t used = 0;
  try {
    value = std::stoi(std::string(text), &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || used == 0 || value < min)
    throw BadValue("expected " + expected() + ", got '" + std::string(text) + "'");
}

void Keywords::parse(std::string_view text, std::string& value) const {
  if (std::find(words.begin(), words.end(), text) == words.end()) {
    throw BadValue(unknown_word("value", text, words));
  }
  value = text;
}

}  // namespace coldspray::case_file
