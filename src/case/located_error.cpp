#include "case/located_error.hpp"

#include "core/error.hpp"

namespace coldspray::case_file {

std::string where(const Case& c, std::string_view key) {
  std::string path(key);
  while (!path.empty()) {
    if (const auto it = c.key_locations.find(path); it != c.key_locations.end()) return it->second;
    const std::size_t dot = path.rfind('.');
    path.resize(dot == std::string::npos ? 0 : dot);
  }
  return c.source_file;
}

void fail_at(const Case& c, const std::string& key, const std::string& message) {
  throw InputError(where(c, key), key, message);
}

}  // namespace coldspray::case_file
