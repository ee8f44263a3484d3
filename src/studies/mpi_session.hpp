// Which share of a study this process runs: under an MPI launcher (mpirun sets
// OMPI_COMM_WORLD_SIZE or PMI_SIZE) MPI is initialised and the rank and size come from it;
// otherwise, or in a build without MPI, the process is rank 0 of 1 and MPI is never touched.
#pragma once

#include <string>

namespace coldspray::studies {

class MpiSession {
 public:
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  int rank() const { return rank_; }
  int size() const { return size_; }
  // Waits for every rank (no-op without MPI).
  void barrier() const;
  // Rank 0's `text` on every rank (collective; `text` itself without MPI).
  std::string from_rank0(std::string text) const;

 private:
  int rank_ = 0;
  int size_ = 1;
  bool initialised_ = false;
};

}  // namespace coldspray::studies
