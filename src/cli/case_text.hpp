// Writing generated case files (`coldspray impact`, `coldspray deposit`): lengths and numbers as
// short as read back to the same value, wrapped comment paragraphs, folder-safe names.
#pragma once

#include <string>
#include <string_view>

#include "case/case.hpp"

namespace coldspray::cli {

// A length in um, as short as reads back to (nearly) the same double: 12 significant digits
// drop the noise of unit conversion (0.7e-6 * 1e6 = 0.7000000000000001) that a user never typed.
std::string um(double metres);
std::string vector_um(const case_file::Vec3& v);
std::string number(double x);
// "14", "22.5": a diameter or speed in a case's name.
std::string short_number(double x);

// Keeps letters, digits, '.', '-' and '_' so the name is a folder name (case_schema.hpp).
std::string folder_safe(std::string text);

// A comment paragraph, wrapped at word boundaries to the repository's 100 columns.
void append_comment(std::string& y, std::string_view text);

}  // namespace coldspray::cli
