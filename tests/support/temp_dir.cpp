#include "temp_dir.hpp"

#include <cstdlib>
#include <filesystem>
#include <mutex>
#include <stdexcept>
#include <vector>

namespace coldspray::testing {

namespace {

// The folders this test program made, removed when it exits (kept with
// COLDSPRAY_KEEP_TEST_DIRS=1, to look at a failing test's files).
class Made {
 public:
  void add(const std::string& dir) {
    const std::lock_guard<std::mutex> lock(mutex_);
    dirs_.push_back(dir);
  }
  ~Made() {
    if (std::getenv("COLDSPRAY_KEEP_TEST_DIRS") != nullptr) return;
    for (const std::string& dir : dirs_) {
      std::error_code ignored;
      std::filesystem::remove_all(dir, ignored);
    }
  }

 private:
  std::mutex mutex_;
  std::vector<std::string> dirs_;
};

Made& made() {
  static Made registry;
  return registry;
}

}  // namespace

std::string make_temp_dir(const std::string& prefix) {
  // mkdtemp replaces the trailing six characters of the template.
  std::string path =
      (std::filesystem::temp_directory_path() / ("coldspray-" + prefix + "-")).string() +
      std::string(6, 'X');
  if (::mkdtemp(path.data()) == nullptr) throw std::runtime_error("mkdtemp failed");
  made().add(path);
  return path;
}

}  // namespace coldspray::testing
