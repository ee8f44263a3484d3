// Probes: Lagrangian gauges, like the embedded gauges of plate-impact experiments. Each follows
// the material point nearest to its position at t = 0 and records the requested fields; NaN once
// that point has left the grid (mpm/departures.hpp).
#pragma once

#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "bodies/bodies.hpp"
#include "case/case.hpp"
#include "io/appended_file.hpp"

namespace coldspray::run {

class ProbeWriter {
 public:
  // Opens path and writes the header time,NAME.FIELD,...; does nothing if there are no probes.
  ProbeWriter(const std::vector<case_file::Probe>& probes, const bodies::Bodies& s,
              const std::filesystem::path& path, io::Opening opening);
  void record(const bodies::Bodies& s);
  // The table, if there are probes.
  const io::AppendedFile* file() const { return out_ ? &*out_ : nullptr; }

 private:
  // The point by its body and its index at t = 0 (Points::id), which points leaving the grid do
  // not change.
  struct Column {
    std::uint16_t body;
    std::uint32_t id;
    int field;
  };
  std::vector<Column> columns_;
  std::optional<io::AppendedFile> out_;
};

// The value of a probe field at a point; the field names are those of docs/input-reference.md.
// Returns -1 for an unknown name (the case parser has already rejected those).
int probe_field_index(const std::string& name);
double probe_value(const bodies::Bodies& s, std::size_t p, int field);

}  // namespace coldspray::run
