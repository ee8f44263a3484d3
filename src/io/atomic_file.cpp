#include "io/atomic_file.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cstring>
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

constexpr std::string_view kTemporary = ".tmp";

fs::path temporary_for(const fs::path& path) {
  return path.string() + fmt::format("{}{}", kTemporary, ::getpid());
}

// Whether `name` is NAME.tmpPID, as temporary_for() makes them.
bool is_temporary(const std::string& name) {
  const std::size_t at = name.rfind(kTemporary);
  if (at == std::string::npos || at == 0 || at + kTemporary.size() == name.size()) return false;
  return std::all_of(name.begin() + static_cast<std::ptrdiff_t>(at + kTemporary.size()), name.end(),
                     [](unsigned char c) { return std::isdigit(c) != 0; });
}

[[noreturn]] void write_failed(const fs::path& path, int error) {
  throw RunFault(fmt::format("writing '{}' failed: {}", path.string(), std::strerror(error)));
}

// fsync of `path` (a file, or a folder after a rename in it); a failure names `target`.
void sync(const fs::path& path, const fs::path& target) {
  const int fd = ::open(path.c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) write_failed(target, errno);
  const int synced = ::fsync(fd);
  const int error = errno;
  ::close(fd);
  // EINVAL: a file system that cannot sync (some special ones); nothing more to do there.
  if (synced != 0 && error != EINVAL) write_failed(target, error);
}

}  // namespace

void require_replaceable(const fs::path& path, const std::string& where) {
  // fs::absolute("") throws: `material-test --out ''` was an internal error (exit 1).
  if (path.empty()) throw InputError(where, "", "an empty path: give the name of a file");
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

void require_writable(const fs::path& path, const std::string& where) {
  require_replaceable(path, where);
  // Root may write where the permissions say no, and a read-only mount says no to everyone:
  // only creating a file tells.
  const fs::path probe = temporary_for(path);
  const int fd = ::open(probe.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0644);
  const int error = errno;
  if (fd >= 0) {
    ::close(fd);
    ::unlink(probe.c_str());
    return;
  }
  throw InputError(where, "",
                   fmt::format("cannot write '{}': {}", path.string(), std::strerror(error)));
}

void write_atomically(const fs::path& path, const std::function<void(std::ostream&)>& write) {
  require_replaceable(path);
  const fs::path temporary = temporary_for(path);
  try {
    std::ofstream out(temporary, std::ios::binary | std::ios::trunc);
    if (!out) write_failed(path, errno);
    write(out);
    out.close();  // fails if the last of the data cannot be written
    if (!out) write_failed(path, errno);
    sync(temporary, path);
    std::error_code ec;
    fs::rename(temporary, path, ec);
    if (ec) write_failed(path, ec.value());
  } catch (...) {
    std::error_code ignored;
    fs::remove(temporary, ignored);
    throw;
  }
  sync(fs::absolute(path).parent_path(), path);
}

void sync_to_disk(const fs::path& path) { sync(path, path); }

void remove_stale_temporaries(const fs::path& folder) {
  std::error_code ec;
  for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec))
    if (it->is_regular_file(ec) && is_temporary(it->path().filename().string()))
      fs::remove(it->path(), ec);
}

}  // namespace coldspray::io
