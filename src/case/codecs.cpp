#include "case/codecs.hpp"

#include <algorithm>

namespace coldspray::case_file {

void Flag::parse(std::string_view text, bool& value) const {
  if (text != "true" && text != "false") {
    throw BadValue("expected true or false, got '" + std::string(text) + "'");
  }
  value = text == "true";
}

void Keywords::parse(std::string_view text, std::string& value) const {
  if (std::find(words.begin(), words.end(), text) == words.end()) {
    throw BadValue(unknown_word("value", text, words));
  }
  value = text;
}

}  // namespace coldspray::case_file
