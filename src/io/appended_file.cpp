#include "io/appended_file.hpp"

#include <fmt/format.h>

#include <fstream>

#include "core/error.hpp"

namespace coldspray::io {

namespace {

void write(const std::filesystem::path& path, std::string_view text, std::ios::openmode mode) {
  std::ofstream out(path, std::ios::binary | mode);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.flush();
  if (!out) throw RunFault(fmt::format("cannot write '{}'", path.string()));
}

}  // namespace

AppendedFile::AppendedFile(std::filesystem::path path, std::string_view header)
    : path_(std::move(path)) {
  write(path_, header, std::ios::trunc);
}

void AppendedFile::append(std::string_view text) { write(path_, text, std::ios::app); }

}  // namespace coldspray::io
