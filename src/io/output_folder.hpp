// Where results go: a folder that a command creates if missing and must be able to write in.
// Its faults are the user's choice of path, so they are input errors (exit 2) with the reason,
// not a filesystem exception (exit 1) raised halfway through a run.
#pragma once

#include <filesystem>

namespace coldspray::io {

// Creates `folder` and its parents if missing and checks that a file can be created in it.
// Throws InputError naming the folder if it is a file, lies under a file, or cannot be created
// or written in (with the system's reason).
void make_output_folder(const std::filesystem::path& folder);

}  // namespace coldspray::io
