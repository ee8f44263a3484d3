#include "run/run_id.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <fstream>
#include <random>

#include "core/error.hpp"
#include "io/atomic_file.hpp"

namespace coldspray::run {

namespace {

constexpr std::size_t kIdDigits = 32;

bool is_id(const std::string& text) {
  return text.size() == kIdDigits && std::all_of(text.begin(), text.end(), [](unsigned char c) {
           return std::isxdigit(c) != 0;
         });
}

}  // namespace

std::string new_run_id() {
  std::random_device entropy;
  std::string id;
  for (std::size_t k = 0; k < kIdDigits / 8; ++k) id += fmt::format("{:08x}", entropy());
  return id;
}

void write_run_id(const std::filesystem::path& folder, const std::string& id) {
  io::write_atomically(folder / kRunIdFile, [&](std::ostream& out) { out << id << "\n"; });
}

std::string read_run_id(const std::filesystem::path& folder) {
  const std::filesystem::path path = folder / kRunIdFile;
  std::ifstream in(path);
  std::string id;
  std::getline(in, id);
  if (!is_id(id))
    throw InputError(path.string(), "",
                     std::filesystem::exists(path)
                         ? "is not a run id: the folder's run cannot be told from another's"
                         : "is missing: not a run folder of this coldspray, or one changed since");
  return id;
}

}  // namespace coldspray::run
