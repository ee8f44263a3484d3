#include "cli/thread_count.hpp"

#include <fmt/format.h>
#include <omp.h>

#include <charconv>
#include <string>

namespace coldspray::cli {

CLI::Validator machine_threads() {
  const int processors = omp_get_num_procs();
  return CLI::Validator(
      [processors](const std::string& text) -> std::string {
        long count = 0;
        const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), count);
        if (ec == std::errc() && end == text.data() + text.size() && count >= 1 &&
            count <= processors)
          return "";
        return fmt::format("'{}': give a whole number from 1 to {}, the processors of this machine",
                           text, processors);
      },
      fmt::format("1..{}", processors));
}

}  // namespace coldspray::cli
