// An HDF5 file of named datasets (Debian's libhdf5, C API): one-dimensional arrays of numbers,
// two-dimensional ones (rows of fixed-size records, such as a 3x3 tensor per point) and
// strings, each under a path such as "points/velocity_x" (groups created as needed). The
// checkpoints (run/checkpoints.hpp) are such files, readable by h5dump and h5py.
//
// HDF5 never touches the disk: a new file is built in memory (the core driver) and save()
// writes its bytes sealed with a checksum (io/sealed_image.hpp) by an atomic, synced write; a
// file read is read whole, its checksum checked, and opened from memory. So a full disk is one
// failed write of ours, reported as such, and never a half-closed HDF5 file that the library's
// exit handlers trip over; a damaged or cut file is refused before any dataset is read.
#pragma once

#include <hdf5.h>

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

namespace coldspray::io {

// The HDF5 type of each element type a dataset may hold.
template <class T>
hid_t hdf5_type() {
  if constexpr (std::is_same_v<T, double>) return H5T_NATIVE_DOUBLE;
  if constexpr (std::is_same_v<T, std::uint8_t>) return H5T_NATIVE_UINT8;
  if constexpr (std::is_same_v<T, std::uint16_t>) return H5T_NATIVE_UINT16;
  if constexpr (std::is_same_v<T, std::uint32_t>) return H5T_NATIVE_UINT32;
  if constexpr (std::is_same_v<T, std::uint64_t>) return H5T_NATIVE_UINT64;
  if constexpr (std::is_same_v<T, std::int64_t>) return H5T_NATIVE_INT64;
  if constexpr (std::is_same_v<T, int>) return H5T_NATIVE_INT;
}

class Hdf5File {
 public:
  enum class Mode { Create, Read };
  // Create: a new file in memory, for save() to write to `path`; Read: an existing one, which
  // must be a regular file sealed by save() (InputError naming it otherwise). Throws RunFault
  // (Create) or InputError (Read) naming the file when HDF5 cannot.
  Hdf5File(const std::filesystem::path& path, Mode mode);
  ~Hdf5File();
  Hdf5File(const Hdf5File&) = delete;
  Hdf5File& operator=(const Hdf5File&) = delete;

  // `rows` x `columns` elements of T from `data`, row after row (columns 1: a 1-D dataset).
  template <class T>
  void write(const std::string& name, const T* data, std::size_t rows, std::size_t columns = 1) {
    write_raw(name, hdf5_type<T>(), data, rows, columns);
  }
  // The dataset's elements into `data`, which must hold `rows` x `columns` of them: the dataset
  // must have exactly that shape (an InputError names the file and the dataset otherwise).
  template <class T>
  void read(const std::string& name, T* data, std::size_t rows, std::size_t columns = 1) const {
    read_raw(name, hdf5_type<T>(), data, rows, columns);
  }
  // Whether the file holds a dataset of that name.
  bool has(const std::string& name) const;
  // The number of rows of a dataset.
  std::size_t rows(const std::string& name) const;

  void write_string(const std::string& name, const std::string& text);
  std::string read_string(const std::string& name) const;

  const std::filesystem::path& path() const { return path_; }

  // Writes a created file to its path: sealed, to a temporary file that is synced and renamed
  // (io/atomic_file.hpp). RunFault if the write fails; the path is then left as it was.
  void save();

 private:
  void write_raw(const std::string& name, hid_t type, const void* data, std::size_t rows,
                 std::size_t columns);
  void read_raw(const std::string& name, hid_t type, void* data, std::size_t rows,
                std::size_t columns) const;
  hid_t open_dataset(const std::string& name) const;

  std::filesystem::path path_;
  std::vector<char> image_;  // a file read: its bytes, which HDF5 reads from memory
  hid_t file_ = -1;
};

}  // namespace coldspray::io
