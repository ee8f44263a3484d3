#include "run/contact_history.hpp"

#include <fmt/format.h>

#include <string>

namespace coldspray::run {

ContactHistoryWriter::ContactHistoryWriter(const std::filesystem::path& path, io::Opening opening)
    : out_(path, "time,body,other,fx,fy,fz\n", opening) {}

void ContactHistoryWriter::record(const bodies::Bodies& s) {
  const std::size_t bodies = s.bodies.size();
  std::string rows;
  if (s.dt > 0.0)
    for (std::size_t a = 0; a < bodies; ++a)
      for (std::size_t b = a + 1; b < bodies; ++b) {
        const auto& impulse = s.contact_impulse[a * bodies + b];
        if (impulse[0] == 0.0 && impulse[1] == 0.0 && impulse[2] == 0.0) continue;
        rows +=
            fmt::format("{:.10g},{},{},{:.10g},{:.10g},{:.10g}\n", s.time, s.bodies[a].name,
                        s.bodies[b].name, impulse[0] / s.dt, impulse[1] / s.dt, impulse[2] / s.dt);
      }
  if (!rows.empty()) out_.append(rows);
}

}  // namespace coldspray::run
