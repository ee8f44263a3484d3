// Writing generated case files (`coldspray impact`, `coldspray deposit`): lengths and numbers as
// short as read back to the same value, wrapped comment paragraphs, folder-safe names.
#pragma once

#include <string>
#include <string_view>

#include "case/case.hpp"

namespace coldspray::setups {

// A length in um, as short as reads back to (nearly) the same double: 12 significant digits
// drop the noise of unit conversion (0.7e-6 * 1e6 = 0.7000000000000001) that a user never typed.
std::string um(double metres);
std::string vector_um(const case_file::Vec3& v);
std::string number(double x);
// "14", "22.5": a diameter or speed in a case's name.
std::string short_number(double x);

// Keeps letters, digits, '.', '-' and '_' so the name is a folder name (case_schema.hpp).
std::string folder_safe(std::string text);

// A comment paragraph, wrapped at word boundaries to the repository's 100 columns; control
// characters (a newline in an option's value) as spaces, so that the comment stays one.
void append_comment(std::string& y, std::string_view text);

// `text` with its control characters as spaces: a "# ..." line that stays a comment.
std::string one_line(std::string text);

// `text` as a YAML scalar that reads back as written whatever it holds: plain when that is safe
// (al-ptw, "22 um sphere at 790 m/s, 3d"), else double-quoted. A name the user gave (a
// material, a description) pasted bare was YAML: `--material 'al-ptw # x'` wrote a case of
// al-ptw, and `--material '[x'` broke the generated case's syntax, reported at a line of it the
// user never saw.
std::string yaml_scalar(std::string_view text);

}  // namespace coldspray::setups
