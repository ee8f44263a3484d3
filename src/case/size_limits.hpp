// The caps that keep a case from exhausting the memory or running for ever, checked when it is
// loaded (by `check`, before `run` allocates anything): the points, the MPM grid's nodes, the
// steps, and output intervals not far shorter than a step. docs/reliability.md, "Input that cannot
// crash or stall", gives the defaults and how they are computed.
#pragma once

#include <cstdint>
#include <string>

#include "case/case.hpp"
#include "case/document.hpp"

namespace coldspray::case_file {

// Memory one item costs, for the caps' defaults: measured peaks with room to spare. A 3D MPM run
// of 136k points on 64k nodes peaked at 108 MB, about 800 B per point with its share of the grid;
// the PD paper's quarter impact at D/25 (100k points, 168 bonds each) at 333 MB, 3.3 kB per
// point. A peridynamic point is taken as its own state and 24 B per bond of its family, the
// bonds counted as 4/3 pi (horizon_factor + 1/2)^3 (180 at the default 3: partial volumes
// reach half a spacing beyond the horizon), 6.4 kB at the default.
inline constexpr double kMpmBytesPerPoint = 1024.0;
inline constexpr double kGridBytesPerNode = 256.0;
inline constexpr double kPdBytesPerPoint = 2048.0;
inline constexpr double kPdBytesPerBond = 24.0;

// The memory available to a run now: MemAvailable of /proc/meminfo, or else the free physical
// pages; 4 GiB if neither can be read.
double available_memory_bytes();

// A cap from limits.KEY, or from the available memory at the cost of one item; with the words
// that say which, for messages ("limits.max_points = 1e+06", "limits.max_points, by default
// 2.41e+07: the 24.6 GB of memory available at 1024 bytes per point").
struct SizeCap {
  double value;
  std::string source;
};
// limits.max_points of the case: for its solver, from the cost of a point of it.
SizeCap point_cap(const Case& c);

// InputError, located at the key to change, when the case's estimated points (in total),
// grid nodes or steps (case/size_estimate.hpp) exceed limits.max_points, max_grid_nodes or
// max_steps (the first two by default the available memory over the cost of one), or when
// output.history_interval or snapshot_interval is positive but less than a thousandth of the
// first step.
void check_size_limits(const Document& doc, const Case& c);

}  // namespace coldspray::case_file
