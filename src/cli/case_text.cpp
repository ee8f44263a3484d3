#include "cli/case_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace coldspray::cli {

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

void append_comment(std::string& y, std::string_view text) {
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

}  // namespace coldspray::cli
