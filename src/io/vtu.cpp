#include "io/vtu.hpp"

#include <fmt/format.h>

#include <cstring>
#include <ostream>

#include "io/atomic_file.hpp"

namespace coldspray::io {

namespace {

template <class T>
std::vector<char> to_bytes(const std::vector<T>& v) {
  std::vector<char> bytes(v.size() * sizeof(T));
  if (!v.empty()) std::memcpy(bytes.data(), v.data(), bytes.size());
  return bytes;
}

// Interleaves three component arrays into one (x0 y0 z0 x1 ...).
std::vector<double> interleave(const std::array<std::vector<double>, 3>& a) {
  std::vector<double> out(3 * a[0].size());
  for (std::size_t i = 0; i < a[0].size(); ++i)
    for (int d = 0; d < 3; ++d) out[3 * i + d] = a[d][i];
  return out;
}

}  // namespace

VtuPointCloud::VtuPointCloud(const std::array<std::vector<double>, 3>& positions)
    : count_(positions[0].size()),
      points_{"Points", "Float64", 3, to_bytes(interleave(positions))} {}

void VtuPointCloud::add_scalar(std::string name, const std::vector<double>& values) {
  fields_.push_back({std::move(name), "Float64", 1, to_bytes(values)});
}

void VtuPointCloud::add_vector(std::string name, const std::array<std::vector<double>, 3>& v) {
  fields_.push_back({std::move(name), "Float64", 3, to_bytes(interleave(v))});
}

void VtuPointCloud::add_int(std::string name, const std::vector<std::int32_t>& values) {
  fields_.push_back({std::move(name), "Int32", 1, to_bytes(values)});
}

void VtuPointCloud::add_byte(std::string name, const std::vector<std::uint8_t>& values) {
  fields_.push_back({std::move(name), "UInt8", 1, to_bytes(values)});
}

void VtuPointCloud::write(const std::filesystem::path& path) const {
  // One vertex cell per point.
  std::vector<std::int64_t> connectivity(count_), offsets(count_);
  for (std::size_t i = 0; i < count_; ++i) {
    connectivity[i] = static_cast<std::int64_t>(i);
    offsets[i] = static_cast<std::int64_t>(i + 1);
  }
  const std::vector<std::uint8_t> types(count_, 1);  // VTK_VERTEX
  const std::vector<Array> cells = {{"connectivity", "Int64", 1, to_bytes(connectivity)},
                                    {"offsets", "Int64", 1, to_bytes(offsets)},
                                    {"types", "UInt8", 1, to_bytes(types)}};

  write_atomically(path, [&](std::ostream& out) {
    std::uint64_t offset = 0;
    auto declare = [&](const Array& a, bool named) {
      out << fmt::format(R"(        <DataArray type="{}"{} NumberOfComponents="{}" )"
                         R"(format="appended" offset="{}"/>)"
                         "\n",
                         a.type, named ? fmt::format(R"( Name="{}")", a.name) : "", a.components,
                         offset);
      offset += sizeof(std::uint64_t) + a.bytes.size();
    };
    out << "<?xml version=\"1.0\"?>\n"
           "<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" byte_order=\"LittleEndian\" "
           "header_type=\"UInt64\">\n  <UnstructuredGrid>\n";
    out << fmt::format("    <Piece NumberOfPoints=\"{}\" NumberOfCells=\"{}\">\n", count_, count_);
    out << "      <PointData>\n";
    for (const Array& a : fields_) declare(a, true);
    out << "      </PointData>\n      <Points>\n";
    declare(points_, false);
    out << "      </Points>\n      <Cells>\n";
    for (const Array& a : cells) declare(a, true);
    out << "      </Cells>\n    </Piece>\n  </UnstructuredGrid>\n"
           "  <AppendedData encoding=\"raw\">\n   _";
    auto append = [&](const Array& a) {
      const std::uint64_t size = a.bytes.size();
      out.write(reinterpret_cast<const char*>(&size), sizeof(size));
      out.write(a.bytes.data(), static_cast<std::streamsize>(a.bytes.size()));
    };
    for (const Array& a : fields_) append(a);
    append(points_);
    for (const Array& a : cells) append(a);
    out << "\n  </AppendedData>\n</VTKFile>\n";
  });
}

void PvdCollection::add(double time, const std::string& relative_file) {
  entries_.emplace_back(time, relative_file);
  write();
}

std::vector<double> PvdCollection::times() const {
  std::vector<double> t;
  for (const auto& entry : entries_) t.push_back(entry.first);
  return t;
}

std::vector<std::string> PvdCollection::files() const {
  std::vector<std::string> f;
  for (const auto& entry : entries_) f.push_back(entry.second);
  return f;
}

void PvdCollection::assign(const std::vector<double>& times,
                           const std::vector<std::string>& files) {
  entries_.clear();
  for (std::size_t k = 0; k < times.size(); ++k) entries_.emplace_back(times[k], files[k]);
  write();
}

void PvdCollection::write() const {
  write_atomically(path_, [&](std::ostream& out) {
    out << "<?xml version=\"1.0\"?>\n<VTKFile type=\"Collection\" version=\"0.1\">\n"
           "  <Collection>\n";
    for (const auto& [t, file] : entries_)
      out << fmt::format("    <DataSet timestep=\"{:.10g}\" file=\"{}\"/>\n", t, file);
    out << "  </Collection>\n</VTKFile>\n";
  });
}

}  // namespace coldspray::io
