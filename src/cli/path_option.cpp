#include "cli/path_option.hpp"

#include <string>

namespace coldspray::cli {

CLI::Validator given_path() {
  return CLI::Validator(
      [](const std::string& text) -> std::string {
        return text.empty() ? "an empty path: give the name of a file or folder" : "";
      },
      "PATH");
}

}  // namespace coldspray::cli
