// ParaView output: a point cloud as a VTK XML UnstructuredGrid (.vtu) of vertex cells with
// binary appended data, and the .pvd collection that lists snapshots by time.
#pragma once

#include <array>
#include <cstdint>
#include <filesystem>
#include <string>
#include <utility>
#include <vector>

namespace coldspray::io {

class VtuPointCloud {
 public:
  // Positions by axis, each of the same length.
  explicit VtuPointCloud(const std::array<std::vector<double>, 3>& positions);

  void add_scalar(std::string name, const std::vector<double>& values);
  void add_vector(std::string name, const std::array<std::vector<double>, 3>& values);
  void add_int(std::string name, const std::vector<std::int32_t>& values);
  void add_byte(std::string name, const std::vector<std::uint8_t>& values);

  // Writes atomically (io/atomic_file.hpp).
  void write(const std::filesystem::path& path) const;

 private:
  struct Array {
    std::string name;
    std::string type;  // VTK type name
    int components;
    std::vector<char> bytes;
  };
  std::size_t count_;
  Array points_;
  std::vector<Array> fields_;
};

// A .pvd collection: call add() after each snapshot; it rewrites the file atomically so it is
// always valid, even if the run stops.
class PvdCollection {
 public:
  explicit PvdCollection(std::filesystem::path path) : path_(std::move(path)) {}
  void add(double time, const std::string& relative_file);
  // The entries, as times and file names; setting them rewrites the collection.
  std::vector<double> times() const;
  std::vector<std::string> files() const;
  void assign(const std::vector<double>& times, const std::vector<std::string>& files);

 private:
  void write() const;

  std::filesystem::path path_;
  std::vector<std::pair<double, std::string>> entries_;
};

}  // namespace coldspray::io
