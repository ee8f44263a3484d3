#include "io/folder_lock.hpp"

#include <fcntl.h>
#include <fmt/format.h>
#include <sys/file.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <iostream>
#include <string>

#include "core/error.hpp"

namespace coldspray::io {

namespace {

// The pid the holder wrote into the lock file, or "unknown" (it may be writing it now).
std::string holder_pid(int fd) {
  char text[32] = {};
  const ssize_t n = ::pread(fd, text, sizeof text - 1, 0);
  std::string pid(text, n > 0 ? static_cast<std::size_t>(n) : 0);
  while (!pid.empty() && (pid.back() == '\n' || pid.back() == '\0')) pid.pop_back();
  return pid.empty() ? "unknown" : pid;
}

}  // namespace

FolderLock::FolderLock(const std::filesystem::path& folder, const std::string& where) {
  const std::filesystem::path path = folder / kLockFile;
  fd_ = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd_ < 0)
    throw InputError(where, "",
                     fmt::format("cannot lock '{}': {}", folder.string(), std::strerror(errno)));
  if (::flock(fd_, LOCK_EX | LOCK_NB) == 0) {
    // The pid is only for the message a refused process prints: the lock holds without it.
    const std::string pid = fmt::format("{}\n", ::getpid());
    const bool noted = ::ftruncate(fd_, 0) == 0 &&
                       ::pwrite(fd_, pid.data(), pid.size(), 0) == static_cast<ssize_t>(pid.size());
    (void)noted;
    return;
  }
  const int error = errno;
  if (error == EWOULDBLOCK) {
    const std::string holder = holder_pid(fd_);
    ::close(fd_);
    fd_ = -1;
    throw InputError(where, "",
                     fmt::format("'{}' is in use by another coldspray process (pid {}); wait for "
                                 "it to end, or choose another folder",
                                 folder.string(), holder));
  }
  std::cerr << fmt::format("warning: cannot lock '{}' ({}); going on without a lock\n",
                           folder.string(), std::strerror(error));
}

FolderLock::~FolderLock() {
  if (fd_ < 0) return;
  // Released, the lock file names nobody (a killed holder's pid stays: the lock itself is gone).
  const bool cleared = ::ftruncate(fd_, 0) == 0;
  (void)cleared;
  ::close(fd_);
}

}  // namespace coldspray::io
