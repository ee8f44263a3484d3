// Writing a result file so that a reader never sees it half-written: the content goes to a
// temporary file beside the target (TARGET.tmpPID), which is synced to the disk and renamed over
// the target only once complete, and the folder synced after the rename, so that the target is
// the old file or the whole new one even after a crash of the machine.
#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>
#include <string>

namespace coldspray::io {

// Checks that `path` can be written atomically: its folder exists, and `path` is missing or a
// regular file. The rename would put a regular file in place of whatever else is there: a
// symbolic link (not the file it points to), a fifo, or a device (as root, /dev/full). Throws
// InputError naming `where` (an option, or empty) and the path if not.
void require_replaceable(const std::filesystem::path& path, const std::string& where = "");

// require_replaceable, and that a file can be created in its folder (not read-only, permitted):
// for an output the user names on the command line, checked before the work it would hold.
void require_writable(const std::filesystem::path& path, const std::string& where);

// Calls `write` with a stream to a temporary file in the target's folder, syncs it and renames
// it to `path`. First require_replaceable(path) (InputError); if `write` throws or any write,
// sync or rename fails (a full disk), the temporary file is removed, `path` is left as it was,
// and the exception (or a RunFault naming the file and the system's reason) propagates.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write);

// fsync(2) of a file, or of a folder's entries: RunFault naming the file if the system cannot.
void sync_to_disk(const std::filesystem::path& path);

// Removes what writes killed midway (kill -9) left in `folder`: files named like write_atomically's
// temporaries. Only for a folder this process holds (io/folder_lock.hpp), where no other
// process is writing.
void remove_stale_temporaries(const std::filesystem::path& folder);

}  // namespace coldspray::io
