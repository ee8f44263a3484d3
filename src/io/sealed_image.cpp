#include "io/sealed_image.hpp"

#include <fmt/format.h>
#include <zlib.h>

#include <algorithm>
#include <cstring>
#include <string>

#include "core/error.hpp"

namespace coldspray::io {

namespace {

constexpr const char* kMagic = "coldspray sealed file 1\n";

// CRC-32 of `bytes` after the header, in pieces zlib's uInt length can hold.
unsigned long crc_after_header(const std::vector<char>& bytes) {
  unsigned long crc = crc32(0L, Z_NULL, 0);
  for (std::size_t at = kSealBytes; at < bytes.size();) {
    const std::size_t piece = std::min<std::size_t>(bytes.size() - at, 1u << 30);
    crc = crc32(crc, reinterpret_cast<const Bytef*>(bytes.data() + at), static_cast<uInt>(piece));
    at += piece;
  }
  return crc;
}

std::string header_for(const std::vector<char>& bytes) {
  return fmt::format("{}length {}\ncrc32 {:08x}\n", kMagic, bytes.size(), crc_after_header(bytes));
}

}  // namespace

void seal(std::vector<char>& bytes) {
  const std::string header = header_for(bytes);
  std::fill(bytes.begin(), bytes.begin() + kSealBytes, '\0');
  std::memcpy(bytes.data(), header.data(), header.size());
}

void check_seal(const std::vector<char>& bytes, const std::filesystem::path& path) {
  const auto refuse = [&](const std::string& why) { throw InputError(path.string(), "", why); };
  if (bytes.size() < kSealBytes || std::memcmp(bytes.data(), kMagic, std::strlen(kMagic)) != 0)
    refuse(
        "has no checksum header: not a checkpoint, or one of a coldspray before checkpoint "
        "format 3");
  // The header as seal() would write it for these bytes, padding and all: a changed length,
  // checksum or header byte all differ from it.
  std::vector<char> expected(kSealBytes, '\0');
  const std::string header = header_for(bytes);
  std::memcpy(expected.data(), header.data(), std::min(header.size(), kSealBytes));
  if (!std::equal(expected.begin(), expected.end(), bytes.begin()))
    refuse(
        fmt::format("is damaged: its {} bytes do not match the length and CRC-32 it was "
                    "written with (cut short, overwritten, or a flipped bit)",
                    bytes.size()));
}

}  // namespace coldspray::io
