#include "setups/case_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace coldspray::setups {

std::string um(double metres) { return fmt::format("{:.12g} um", metres / 1e-6); }

std::string vector_um(const case_file::Vec3& v) {
  return fmt::format("[{}, {}, {}]", um(v[0]), um(v[1]), um(v[2]));
}

std::string number(double x) { return fmt::format("{:.12g}", x); }

std::string short_number(double x) { return fmt::format("{:.6g}", x); }

std::string folder_safe(std::string text) {
  for (char& ch : text)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.' && ch != '-' && ch != '_')
      ch = '_';
  return text;
}

std::string one_line(std::string text) {
  for (char& ch : text)
    if (std::iscntrl(static_cast<unsigned char>(ch))) ch = ' ';
  return text;
}

namespace {

// Whether `text` reads back as itself as a plain scalar in block context: it starts with a
// letter or digit, holds no ": " (a key), no '#', quote, bracket or control character, does not
// end in ':' or a space (trimmed) and is not YAML's null.
bool plain_safe(std::string_view text) {
  if (text.empty() || !std::isalnum(static_cast<unsigned char>(text.front())) ||
      text.back() == ':' || text.back() == ' ' || text.find(": ") != std::string_view::npos ||
      text == "null" || text == "Null" || text == "NULL")
    return false;
  return std::all_of(text.begin(), text.end(), [](char ch) {
    const auto c = static_cast<unsigned char>(ch);
    return std::isalnum(c) || c >= 0x80 ||
           std::string_view("-_./:, ()+").find(ch) != std::string_view::npos;
  });
}

}  // namespace

std::string yaml_scalar(std::string_view text) {
  if (plain_safe(text)) return std::string(text);
  std::string out = "\"";
  for (const char ch : text) {
    if (ch == '"' || ch == '\\')
      out += {'\\', ch};
    else if (std::iscntrl(static_cast<unsigned char>(ch)))
      out += fmt::format("\\x{:02x}", static_cast<unsigned char>(ch));
    else
      out += ch;
  }
  return out + '"';
}

void append_comment(std::string& y, std::string_view paragraph) {
  const std::string flat = one_line(std::string(paragraph));
  std::string_view text = flat;
  std::size_t row = 1;  // the width of the row being written, "#" included
  y += '#';
  while (!text.empty()) {
    const std::size_t end = std::min(text.find(' '), text.size());
    if (row > 1 && row + 1 + end > 99) {
      y += "\n#";
      row = 1;
    }
    y += ' ';
    y.append(text.substr(0, end));
    row += 1 + end;
    text.remove_prefix(std::min(end + 1, text.size()));
  }
  y += '\n';
}

}  // namespace coldspray::setups
