#include "case/codecs.hpp"

#include <algorithm>
#include <charconv>
#include <system_error>

#include "core/text.hpp"

namespace coldspray::case_file {

void Flag::parse(std::string_view text, bool& value) const {
  if (text != "true" && text != "false") {
    throw BadValue("expected true or false, got '" + std::string(text) + "'");
  }
  value = text == "true";
}

void WholeNumber::parse(std::string_view text, int& value) const {
  // Digits after an optional sign, blanks around them ignored as in a quantity (units.cpp);
  // std::stoi took leading blanks but not trailing ones. from_chars takes '-' but no '+'.
  const std::string_view trimmed = trim(text);
  const bool plus = trimmed.starts_with('+') && !trimmed.substr(1).starts_with('-');
  const std::string_view number = plus ? trimmed.substr(1) : trimmed;
  int parsed = 0;
  const auto [end, ec] = std::from_chars(number.data(), number.data() + number.size(), parsed);
  if (ec != std::errc() || end != number.data() + number.size() || parsed < min)
    throw BadValue("expected " + expected() + ", got '" + std::string(text) + "'");
  value = parsed;
}

void Keywords::parse(std::string_view text, std::string& value) const {
  if (std::find(words.begin(), words.end(), text) == words.end()) {
    throw BadValue(unknown_word("value", text, words));
  }
  value = text;
}

}  // namespace coldspray::case_file
