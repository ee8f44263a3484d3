#include "io/atomic_file.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <fstream>

#include "core/error.hpp"

namespace coldspray::io {

void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write) {
  namespace fs = std::filesystem;
  const fs::path temporary = path.string() + fmt::format(".tmp{}", ::getpid());
  try {
    {
      std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
      if (!out) throw RunFault(fmt::format("cannot write '{}'", path.string()));
      write(out);
      out.flush();
      if (!out) throw RunFault(fmt::format("writing '{}' failed", path.string()));
    }
    fs::rename(temporary, path);
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
}

}  // namespace coldspray::io
