#include "studies/study_lock.hpp"

#include "core/error.hpp"
#include "io/output_folder.hpp"

namespace coldspray::studies {

std::unique_ptr<io::FolderLock> lock_study_folder(const std::filesystem::path& folder,
                                                  const MpiSession& mpi) {
  std::unique_ptr<io::FolderLock> lock;
  std::string refusal;
  if (mpi.rank() == 0) try {
      io::make_output_folder(folder);
      lock = std::make_unique<io::FolderLock>(folder, "--out");
    } catch (const InputError& e) {
      refusal = e.what();
    }
  refusal = mpi.from_rank0(refusal);
  if (!refusal.empty()) throw InputError("", "", refusal);
  return lock;
}

}  // namespace coldspray::studies
