// contact.csv: the contact force between each pair of bodies over time, one row per touching
// pair, so that its size follows the contacts, not bodies squared.
#pragma once

#include <filesystem>

#include "bodies/bodies.hpp"
#include "io/appended_file.hpp"

namespace coldspray::run {

class ContactHistoryWriter {
 public:
  ContactHistoryWriter(const std::filesystem::path& path, io::Opening opening);
  // Rows `time,body,other,fx,fy,fz`: the force on `body` from `other` over the last step (N),
  // for every pair (body before other in `bodies`) that exchanged momentum in it.
  void record(const bodies::Bodies& s);
  const io::AppendedFile& file() const { return out_; }

 private:
  io::AppendedFile out_;
};

}  // namespace coldspray::run
