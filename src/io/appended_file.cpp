#include "io/appended_file.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cstring>
#include <fstream>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace coldspray::io {

namespace {

void write(const std::filesystem::path& path, std::string_view text, std::ios::openmode mode) {
  std::ofstream out(path, std::ios::binary | mode);
  out.write(text.data(), static_cast<std::streamsize>(text.size()));
  out.close();  // fails if the row cannot reach the disk (a full disk)
  if (!out)
    throw RunFault(fmt::format("writing '{}' failed: {}", path.string(), std::strerror(errno)));
}

}  // namespace

AppendedFile::AppendedFile(std::filesystem::path path, std::string_view header, Opening opening)
    : path_(std::move(path)) {
  if (opening == Opening::Create) write(path_, header, std::ios::trunc);
}

void AppendedFile::append(std::string_view text) { write(path_, text, std::ios::app); }

void AppendedFile::sync() const { sync_to_disk(path_); }

std::uintmax_t AppendedFile::length() const { return std::filesystem::file_size(path_); }

void AppendedFile::check_resumable(std::uintmax_t length) const {
  const auto refuse = [&](const std::string& why) {
    throw InputError(path_.string(), "",
                     fmt::format("{}: the run's tables were changed since its checkpoint, so it "
                                 "cannot continue them",
                                 why));
  };
  std::error_code error;
  if (!std::filesystem::is_regular_file(path_, error))
    refuse(std::filesystem::exists(path_, error) ? "is not a regular file" : "is missing");
  const std::uintmax_t now = std::filesystem::file_size(path_, error);
  if (error || now < length)
    refuse(fmt::format("has {} bytes where its checkpoint recorded {}", error ? 0 : now, length));
  char last = '\n';
  std::ifstream in(path_, std::ios::binary);
  if (length > 0) in.seekg(static_cast<std::streamoff>(length - 1)).get(last);
  if (!in || last != '\n') refuse(fmt::format("does not end a row at byte {}", length));
}

void AppendedFile::cut_to(std::uintmax_t length) const {
  std::error_code error;
  std::filesystem::resize_file(path_, length, error);
  if (error)
    throw RunFault(fmt::format("cannot cut '{}' back: {}", path_.string(), error.message()));
}

}  // namespace coldspray::io
