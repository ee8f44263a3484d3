// One process per output folder: an advisory lock (flock(2)) on FOLDER/.coldspray.lock, taken
// by run, restart, impact, deposit, sweep, vcrit and calibrate before they read or write the
// folder and held until they end (the system drops it if the process dies, even by kill -9).
// Two processes writing one folder would interleave its tables.
#pragma once

#include <filesystem>
#include <string>

namespace coldspray::io {

class FolderLock {
 public:
  // Takes the lock of `folder`, which must exist. InputError naming `where` (the option that
  // named the folder) and the holder's pid if another process holds it. On a file system
  // without locks (ENOLCK, EOPNOTSUPP) it warns on stderr and goes on unlocked.
  FolderLock(const std::filesystem::path& folder, const std::string& where);
  ~FolderLock();
  FolderLock(const FolderLock&) = delete;
  FolderLock& operator=(const FolderLock&) = delete;

 private:
  int fd_ = -1;
};

inline constexpr const char* kLockFile = ".coldspray.lock";

}  // namespace coldspray::io
