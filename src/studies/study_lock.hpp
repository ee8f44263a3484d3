// A study's folder held by one launch (io/folder_lock.hpp): rank 0 creates and locks it and
// tells every rank whether it could, so that all the ranks of a second launch on the folder
// stop, not only its rank 0.
#pragma once

#include <filesystem>
#include <memory>

#include "io/folder_lock.hpp"
#include "studies/mpi_session.hpp"

namespace coldspray::studies {

// Creates `folder` if missing and locks it on rank 0 (collective). InputError on every rank if
// rank 0 could not (the folder is unwritable, or another process holds it); the lock (empty on
// the other ranks) is held while the result lives.
std::unique_ptr<io::FolderLock> lock_study_folder(const std::filesystem::path& folder,
                                                  const MpiSession& mpi);

}  // namespace coldspray::studies
