#include "studies/mpi_session.hpp"

#include <cstdlib>

#ifdef COLDSPRAY_HAVE_MPI
#include <mpi.h>
#endif

namespace coldspray::studies {

namespace {

bool under_launcher() {
  return std::getenv("OMPI_COMM_WORLD_SIZE") != nullptr || std::getenv("PMI_SIZE") != nullptr;
}

}  // namespace

MpiSession::MpiSession() {
#ifdef COLDSPRAY_HAVE_MPI
  if (!under_launcher()) return;
  // Only the main thread calls MPI; the sweep's worker threads never do.
  int provided = 0;
  MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank_);
  MPI_Comm_size(MPI_COMM_WORLD, &size_);
  initialised_ = true;
#else
  (void)under_launcher;
#endif
}

MpiSession::~MpiSession() {
#ifdef COLDSPRAY_HAVE_MPI
  if (initialised_) MPI_Finalize();
#endif
}

void MpiSession::barrier() const {
#ifdef COLDSPRAY_HAVE_MPI
  if (initialised_) MPI_Barrier(MPI_COMM_WORLD);
#endif
}

std::string MpiSession::from_rank0(std::string text) const {
#ifdef COLDSPRAY_HAVE_MPI
  if (!initialised_) return text;
  unsigned long long size = text.size();
  MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  text.resize(size);
  if (size > 0) MPI_Bcast(text.data(), static_cast<int>(size), MPI_CHAR, 0, MPI_COMM_WORLD);
#endif
  return text;
}

}  // namespace coldspray::studies
