#include "io/atomic_file.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <fstream>

#include "core/error.hpp"

namespace coldspray::io {

namespace fs = std::filesystem;

namespace {

const char* kind_of(fs::file_type type) {
  switch (type) {
    case fs::file_type::directory:
      return "a folder";
    case fs::file_type::symlink:
      return "a symbolic link";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::fifo:
      return "a fifo";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

}  // namespace

void require_replaceable(const fs::path& path, const std::string& where) {
  std::error_code ec;
  const fs::path folder = fs::absolute(path).parent_path();
  if (!fs::is_directory(folder, ec))
    throw InputError(where, "", fmt::format("no such folder '{}'", folder.string()));
  const fs::file_status status = fs::symlink_status(path, ec);
  if (status.type() == fs::file_type::not_found || status.type() == fs::file_type::regular) return;
  throw InputError(where, "",
                   fmt::format("'{}' is {}; only a regular file is replaced", path.string(),
                               kind_of(status.type())));
}

void write_file_atomically(const fs::path& path,
                           const std::function<void(const fs::path&)>& write) {
  require_replaceable(path);
  const fs::path temporary = path.string() + fmt::format(".tmp{}", ::getpid());
  try {
    write(temporary);
    fs::rename(temporary, path);
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
}

void write_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  write_file_atomically(path, [&](const fs::path& temporary) {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) throw RunFault(fmt::format("cannot write '{}'", path.string()));
    write(out);
    out.flush();
    if (!out) throw RunFault(fmt::format("writing '{}' failed", path.string()));
  });
}

}  // namespace coldspray::io
