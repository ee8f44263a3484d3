#include "io/output_folder.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <fstream>
#include <system_error>

#include "core/error.hpp"

namespace coldspray::io {

namespace fs = std::filesystem;

namespace {

[[noreturn]] void refuse(const fs::path& folder, const std::string& reason) {
  throw InputError(fmt::format("output folder '{}'", folder.string()), "", reason);
}

// The nearest of `folder` and its parents that exists (following symbolic links), or empty.
fs::path existing_ancestor(const fs::path& folder) {
  for (fs::path p = fs::absolute(folder); !p.empty(); p = p.parent_path()) {
    std::error_code ec;
    if (fs::exists(p, ec)) return p;
    if (p == p.parent_path()) break;
  }
  return {};
}

}  // namespace

void make_output_folder(const fs::path& folder) {
  const fs::path nearest = existing_ancestor(folder);
  std::error_code ec;
  if (!nearest.empty() && !fs::is_directory(nearest, ec)) {
    if (nearest == fs::absolute(folder)) refuse(folder, "it is a file, not a folder");
    refuse(folder, fmt::format("'{}' is a file, not a folder", nearest.string()));
  }
  fs::create_directories(folder, ec);
  if (ec) refuse(folder, fmt::format("cannot create it: {}", ec.message()));
  // Root may write where the permissions say no, and a read-only mount says no to everyone:
  // only creating a file tells.
  const fs::path probe = folder / fmt::format(".coldspray-write-test{}", ::getpid());
  const bool writable = static_cast<bool>(std::ofstream(probe));
  fs::remove(probe, ec);
  if (!writable) refuse(folder, "cannot write in it (permission denied or read-only)");
}

}  // namespace coldspray::io
