#include "core/error.hpp"

#include <fmt/format.h>

namespace coldspray {

namespace {
std::string compose(const std::string& where, const std::string& key, const std::string& message) {
  return fmt::format("{}{}{}", where.empty() ? "" : where + ": ",
                     key.empty() ? "" : fmt::format("key '{}': ", key), message);
}
}  // namespace

InputError::InputError(std::string where, std::string key, std::string message)
    : std::runtime_error(compose(where, key, message)),
      where_(std::move(where)),
      key_(std::move(key)),
      message_(std::move(message)) {}

}  // namespace coldspray
