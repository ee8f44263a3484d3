#include "io/hdf5_file.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <iterator>

#include "core/error.hpp"
#include "io/atomic_file.hpp"
#include "io/sealed_image.hpp"

namespace coldspray::io {

namespace {

// HDF5 prints its error stack to stderr by default; our messages say what failed instead.
void silence_hdf5_errors() {
  static const bool silenced = [] { return H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr) >= 0; }();
  (void)silenced;
}

// Closes an HDF5 handle when it goes out of scope.
class Handle {
 public:
  Handle(hid_t id, herr_t (*close)(hid_t)) : id_(id), close_(close) {}
  ~Handle() {
    if (id_ >= 0) close_(id_);
  }
  Handle(const Handle&) = delete;
  Handle& operator=(const Handle&) = delete;
  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }

 private:
  hid_t id_;
  herr_t (*close_)(hid_t);
};

// A regular file's bytes; InputError for anything else (a fifo would block open()).
std::vector<char> read_regular_file(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec))
    throw InputError(path.string(), "",
                     std::filesystem::exists(path, ec) ? "is not a regular file" : "is missing");
  std::ifstream in(path, std::ios::binary);
  std::vector<char> bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  if (in.bad()) throw InputError(path.string(), "", "cannot be read");
  return bytes;
}

// File access through memory (the core driver) without a file behind it, and no HDF5 file
// locks (they fail on file systems without them: NFS, some Lustre mounts).
hid_t in_memory_access() {
  const hid_t access = H5Pcreate(H5P_FILE_ACCESS);
  H5Pset_fapl_core(access, std::size_t{16} << 20, /*backing_store=*/0);
  H5Pset_file_locking(access, false, true);
  // The default (earliest) file format: with HDF5 1.10.8's newer superblock (H5F_LIBVER_V18 and
  // up), the image H5Fget_file_image gives of a file with a user block fails its superblock
  // checksum when opened again. The seal's CRC-32 covers every byte either way.
  return access;
}

}  // namespace

Hdf5File::Hdf5File(const std::filesystem::path& path, Mode mode) : path_(path) {
  silence_hdf5_errors();
  const Handle access(in_memory_access(), H5Pclose);
  if (mode == Mode::Create) {
    const Handle creation(H5Pcreate(H5P_FILE_CREATE), H5Pclose);
    H5Pset_userblock(creation.get(), kSealBytes);  // the room for the seal
    file_ = H5Fcreate((path.string() + " (in memory)").c_str(), H5F_ACC_TRUNC, creation.get(),
                      access.get());
    if (file_ < 0) throw RunFault(fmt::format("cannot create '{}' in memory", path.string()));
    return;
  }
  image_ = read_regular_file(path);
  check_seal(image_, path);
  H5Pset_file_image(access.get(), image_.data(), image_.size());
  // The core driver refuses to open a name that exists on disk: HDF5 gets another.
  file_ = H5Fopen((path.string() + " (in memory)").c_str(), H5F_ACC_RDONLY, access.get());
  if (file_ < 0) throw InputError(path.string(), "", "not a readable HDF5 file");
}

Hdf5File::~Hdf5File() {
  if (file_ >= 0) H5Fclose(file_);
}

void Hdf5File::save() {
  if (H5Fflush(file_, H5F_SCOPE_GLOBAL) < 0)
    throw RunFault(fmt::format("cannot finish '{}' in memory", path_.string()));
  // The image is the file after its user block, which the seal then fills.
  const ssize_t size = H5Fget_file_image(file_, nullptr, 0);
  std::vector<char> bytes(kSealBytes + static_cast<std::size_t>(std::max<ssize_t>(size, 0)));
  if (size <= 0 || H5Fget_file_image(file_, bytes.data() + kSealBytes, size) != size)
    throw RunFault(fmt::format("cannot finish '{}' in memory", path_.string()));
  seal(bytes);
  write_atomically(path_, [&](std::ostream& out) {
    out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
  });
}

void Hdf5File::write_raw(const std::string& name, hid_t type, const void* data, std::size_t rows,
                         std::size_t columns) {
  const std::array<hsize_t, 2> shape{rows, columns};
  const Handle space(H5Screate_simple(columns == 1 ? 1 : 2, shape.data(), nullptr), H5Sclose);
  const Handle links(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(links.get(), 1);
  const Handle set(
      H5Dcreate2(file_, name.c_str(), type, space.get(), links.get(), H5P_DEFAULT, H5P_DEFAULT),
      H5Dclose);
  if (!set.valid() ||
      (rows * columns > 0 && H5Dwrite(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0))
    throw RunFault(fmt::format("writing '{}' of '{}' failed", name, path_.string()));
}

hid_t Hdf5File::open_dataset(const std::string& name) const {
  const hid_t set = has(name) ? H5Dopen2(file_, name.c_str(), H5P_DEFAULT) : -1;
  if (set < 0) throw InputError(path_.string(), name, "missing from the checkpoint");
  return set;
}

bool Hdf5File::has(const std::string& name) const {
  return H5Lexists(file_, name.c_str(), H5P_DEFAULT) > 0;
}

std::size_t Hdf5File::rows(const std::string& name) const {
  const Handle set(open_dataset(name), H5Dclose);
  const Handle space(H5Dget_space(set.get()), H5Sclose);
  std::array<hsize_t, 2> shape{0, 1};
  if (H5Sget_simple_extent_ndims(space.get()) < 1) return 1;  // a scalar dataspace
  H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr);
  return shape[0];
}

void Hdf5File::read_raw(const std::string& name, hid_t type, void* data, std::size_t rows,
                        std::size_t columns) const {
  const Handle set(open_dataset(name), H5Dclose);
  const Handle space(H5Dget_space(set.get()), H5Sclose);
  const int dims = H5Sget_simple_extent_ndims(space.get());
  std::array<hsize_t, 2> shape{0, 1};
  if (dims >= 1 && dims <= 2) H5Sget_simple_extent_dims(space.get(), shape.data(), nullptr);
  if (dims != (columns == 1 ? 1 : 2) || shape[0] != rows || shape[1] != columns)
    throw InputError(path_.string(), name,
                     fmt::format("has shape {}x{} where this run needs {}x{}", shape[0], shape[1],
                                 rows, columns));
  if (rows * columns > 0 && H5Dread(set.get(), type, H5S_ALL, H5S_ALL, H5P_DEFAULT, data) < 0)
    throw InputError(path_.string(), name, "cannot be read");
}

void Hdf5File::write_string(const std::string& name, const std::string& text) {
  const Handle type(H5Tcopy(H5T_C_S1), H5Tclose);
  H5Tset_size(type.get(), std::max<std::size_t>(text.size(), 1));
  const Handle space(H5Screate(H5S_SCALAR), H5Sclose);
  const Handle links(H5Pcreate(H5P_LINK_CREATE), H5Pclose);
  H5Pset_create_intermediate_group(links.get(), 1);
  const Handle set(H5Dcreate2(file_, name.c_str(), type.get(), space.get(), links.get(),
                              H5P_DEFAULT, H5P_DEFAULT),
                   H5Dclose);
  const std::string padded = text.empty() ? std::string(1, '\0') : text;
  if (!set.valid() ||
      H5Dwrite(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, padded.data()) < 0)
    throw RunFault(fmt::format("writing '{}' of '{}' failed", name, path_.string()));
}

std::string Hdf5File::read_string(const std::string& name) const {
  const Handle set(open_dataset(name), H5Dclose);
  const Handle type(H5Dget_type(set.get()), H5Tclose);
  if (H5Tget_class(type.get()) != H5T_STRING)
    throw InputError(path_.string(), name, "is not a string");
  std::string text(H5Tget_size(type.get()), '\0');
  if (H5Dread(set.get(), type.get(), H5S_ALL, H5S_ALL, H5P_DEFAULT, text.data()) < 0)
    throw InputError(path_.string(), name, "cannot be read");
  text.resize(text.find('\0') == std::string::npos ? text.size() : text.find('\0'));
  return text;
}

}  // namespace coldspray::io
