#include "temp_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <stdexcept>

namespace coldspray::testing {

std::string make_temp_dir(const std::string& prefix) {
  // mkdtemp replaces the trailing six characters of the template.
  std::string path =
      (std::filesystem::temp_directory_path() / ("coldspray-" + prefix + "-")).string() +
      std::string(6, 'X');
  if (::mkdtemp(path.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  return path;
}

}  // namespace coldspray::testing
