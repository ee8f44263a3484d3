// Writing a result file so that a reader never sees it half-written: the content goes to a
// temporary file beside the target, which is renamed over the target only once complete.
#pragma once

#include <filesystem>
#include <functional>
#include <iosfwd>

namespace coldspray::io {

// Calls `write` with a stream to a temporary file in the target's folder, then renames it to
// `path`. If `write` throws or the stream fails, the temporary file is removed, `path` is left
// as it was, and the exception (or a RunFault for a failed stream) propagates.
void write_atomically(const std::filesystem::path& path,
                      const std::function<void(std::ostream&)>& write);

}  // namespace coldspray::io
