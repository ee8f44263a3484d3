// A file's whole contents, for tests that compare or search what coldspray wrote.
#pragma once

#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

namespace coldspray::testing {

// The file's bytes as they are (read in binary, so the same on every platform); empty when it
// cannot be read.
inline std::string read_text(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

}  // namespace coldspray::testing
