// A run's identity: a random id drawn when the run starts, written to RUN/run_id.txt and into
// each of its checkpoints, so that a restart continues a folder only from that folder's own
// checkpoints, not from another run's copied in (of the same case or not).
#pragma once

#include <filesystem>
#include <string>

namespace coldspray::run {

// A new id: 128 random bits from the system's entropy source, in hex.
std::string new_run_id();

// RUN/run_id.txt: written atomically; read back (InputError naming the file if it is missing
// or not an id).
void write_run_id(const std::filesystem::path& folder, const std::string& id);
std::string read_run_id(const std::filesystem::path& folder);

inline constexpr const char* kRunIdFile = "run_id.txt";

}  // namespace coldspray::run
