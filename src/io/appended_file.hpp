// A text file that grows by rows as a run goes (history.csv, contact.csv, probes.csv). It is
// opened only for each write, so that a process can keep hundreds of them, as a bond family
// records all its members at once (run/bond_family.hpp), within its open-file limit; each row
// is on disk once append() returns.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string_view>

namespace coldspray::io {

// Create: a new table; Resume: a table a restarted run continues (run/checkpoints.hpp).
enum class Opening { Create, Resume };

class AppendedFile {
 public:
  // Create: creates or empties the file and writes `header`; Resume: leaves the file as it is.
  // Throws RunFault if it cannot.
  AppendedFile(std::filesystem::path path, std::string_view header,
               Opening opening = Opening::Create);
  // Adds `text` at the end. Throws RunFault if it cannot.
  void append(std::string_view text);
  // The rows written so far on the disk (fsync), before a checkpoint records the length.
  void sync() const;
  // The file's length in bytes.
  std::uintmax_t length() const;
  // Whether a restarted run can continue the file from `length`, a length it had: InputError
  // naming the file unless it is a regular file at least that long whose first `length` bytes
  // end a row. Then cutting it back to that length (the rows a restarted run writes again).
  void check_resumable(std::uintmax_t length) const;
  void cut_to(std::uintmax_t length) const;

 private:
  std::filesystem::path path_;
};

}  // namespace coldspray::io
