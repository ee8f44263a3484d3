// Writing a result file so that a reader never sees it half-written: the content goes to a
// temporary file beside the target, which is renamed over the target only once complete.
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

// Calls `write` with a stream to a temporary file in the target's folder, then renames it to
// `path`. First require_replaceable(path) (InputError); if `write` throws or the stream fails,
// the temporary file is removed, `path` is left as it was, and the exception (or a RunFault for a
// failed stream) propagates.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write);

// The same for a file that a library writes by name (an HDF5 checkpoint): `write` is given the
// temporary file's path.
void write_file_atomically(const std::filesystem::path& path,
                           const std::function<void(const std::filesystem::path&)>& write);

}  // namespace coldspray::io
