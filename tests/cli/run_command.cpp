#include "run_command.hpp"

#include <sys/wait.h>

#include <array>
#include <cstdio>
#include <cstdlib>
#include <stdexcept>

#include "temp_dir.hpp"

namespace coldspray::testing {

CommandResult run_coldspray(const std::string& args, const std::string& workdir) {
  const std::string dir = workdir.empty() ? make_temp_dir() : workdir;
  const std::string command =
      "cd '" + dir + "' && '" + std::string(COLDSPRAY_BINARY) + "' " + args + " 2>&1";
  FILE* pipe = ::popen(command.c_str(), "r");
  if (pipe == nullptr) throw std::runtime_error("popen failed");
  CommandResult result;
  std::array<char, 4096> buffer{};
  std::size_t n = 0;
  while ((n = std::fread(buffer.data(), 1, buffer.size(), pipe)) > 0)
    result.output.append(buffer.data(), n);
  const int raw = ::pclose(pipe);
  result.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return result;
}

}  // namespace coldspray::testing
