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

AppendedFile::AppendedFile(std::filesystem::path path, std::string_view header, Opening opening)
    : path_(std::move(path)) {
  if (opening == Opening::Create) write(path_, header, std::ios::trunc);
}

void AppendedFile::append(std::string_view text) { write(path_, text, std::ios::app); }

std::uintmax_t AppendedFile::length() const { return std::filesystem::file_size(path_); }

void AppendedFile::cut_to(std::uintmax_t length) const {
  std::error_code error;
  const std::uintmax_t now = std::filesystem::file_size(path_, error);
  if (error || now < length)
    throw InputError(path_.string(), "",
                     fmt::format("has {} bytes where its checkpoint recorded {}: the run's tables "
                                 "were changed since, so it cannot continue them",
                                 error ? 0 : now, length));
  std::filesystem::resize_file(path_, length);
}

}  // namespace coldspray::io
