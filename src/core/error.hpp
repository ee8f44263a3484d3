// Error types and the exit statuses they map to at the command line.
#pragma once

#include <stdexcept>
#include <string>

namespace coldspray {

// Exit statuses of the coldspray binary.
inline constexpr int kExitOk = 0;
inline constexpr int kExitInternal = 1;  // a bug or an unexpected system failure
inline constexpr int kExitBadInput = 2;  // invalid case file, option or material
inline constexpr int kExitRunFault = 3;  // a fault during a run (NaN, escape, energy blow-up)

// A malformed unit string; carries no location, the caller adds file/line/key.
class UnitError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Bad user input. `where` is "file:line:column" (or "--set KEY", or "--option"), `key` the
// dotted key path ("bodies.particle.radius"); what() gives the full one-line message.
class InputError : public std::runtime_error {
 public:
  InputError(std::string where, std::string key, std::string message);
  const std::string& where() const { return where_; }
  const std::string& key() const { return key_; }
  const std::string& message() const { return message_; }

 private:
  std::string where_;
  std::string key_;
  std::string message_;
};

// A fault while a simulation or material test runs.
class RunFault : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace coldspray
