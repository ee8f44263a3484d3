#include "io/hdf5_file.hpp"

#include <fmt/format.h>

#include <array>

#include "core/error.hpp"

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

}  // namespace

Hdf5File::Hdf5File(const std::filesystem::path& path, Mode mode) : path_(path) {
  silence_hdf5_errors();
  // No file locks: a checkpoint is written to a file of its own and renamed (run/checkpoints.cpp),
  // and the locks HDF5 takes by default fail on file systems without them (NFS, some Lustre
  // mounts of the clusters a user may move to).
  const Handle access(H5Pcreate(H5P_FILE_ACCESS), H5Pclose);
  H5Pset_file_locking(access.get(), false, true);
  file_ = mode == Mode::Create ? H5Fcreate(path.c_str(), H5F_ACC_TRUNC, H5P_DEFAULT, access.get())
                               : H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.get());
  if (file_ >= 0) return;
  if (mode == Mode::Create) throw RunFault(fmt::format("cannot create '{}'", path.string()));
  throw InputError(path.string(), "", "not a readable HDF5 file");
}

Hdf5File::~Hdf5File() {
  if (file_ >= 0) H5Fclose(file_);
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
