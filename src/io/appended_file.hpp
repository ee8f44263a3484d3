// A text file that grows by rows as a run goes (history.csv, contact.csv, probes.csv). It is
// opened only for each write, so that a process can keep hundreds of them, as a bond family
// records all its members at once (run/bond_family.hpp), within its open-file limit; each row
// is on disk once append() returns.
#pragma once

#include <filesystem>
#include <string_view>

namespace coldspray::io {

class AppendedFile {
 public:
  // Creates or empties the file and writes `header`. Throws RunFault if it cannot.
  AppendedFile(std::filesystem::path path, std::string_view header);
  // Adds `text` at the end. Throws RunFault if it cannot.
  void append(std::string_view text);

 private:
  std::filesystem::path path_;
};

}  // namespace coldspray::io
