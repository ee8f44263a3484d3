// A file's bytes that prove themselves: the first kSealBytes hold a text header with the length
// of the whole file and the CRC-32 (zlib's, ISO 3309) of every byte after the header, so that a
// flipped bit anywhere, a file cut short or one grown by a stray write is found before anything
// reads it. A checkpoint (run/checkpoints.hpp) is such a file: HDF5 leaves the header room as
// its "user block", which h5dump and h5py skip.
#pragma once

#include <cstddef>
#include <filesystem>
#include <vector>

namespace coldspray::io {

// The header's size: HDF5's smallest user block.
inline constexpr std::size_t kSealBytes = 512;

// Writes the header into the first kSealBytes of `bytes` (left zero for it).
void seal(std::vector<char>& bytes);

// Throws InputError naming `path` unless `bytes` carries a header that seal() wrote for exactly
// these bytes.
void check_seal(const std::vector<char>& bytes, const std::filesystem::path& path);

}  // namespace coldspray::io
