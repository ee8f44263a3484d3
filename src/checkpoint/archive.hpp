// The two directions of a checkpoint over one list of fields: a state names each of its
// fields once, in a function template over the archive (checkpoint/fields.hpp), and the same
// function writes them (CheckpointWriter) or reads them back (CheckpointReader), so that what
// is saved and what is restored cannot drift apart. A field is a number or a std::vector of
// numbers or of fixed-size Eigen vectors and matrices (one row per element).
#pragma once

#include <Eigen/Core>
#include <array>
#include <concepts>
#include <cstddef>
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "io/hdf5_file.hpp"

namespace coldspray::checkpoint {

template <class T>
concept Number = std::is_arithmetic_v<T>;

// An Eigen vector or matrix of fixed size: stored as a row of its coefficients.
template <class T>
concept FixedEigen = std::derived_from<T, Eigen::DenseBase<T>> &&(T::SizeAtCompileTime > 0);

// bool is stored as a byte.
template <class T>
using Stored = std::conditional_t<std::is_same_v<T, bool>, std::uint8_t, T>;

class CheckpointWriter {
 public:
  static constexpr bool kReading = false;
  explicit CheckpointWriter(io::Hdf5File& file) : file_(file) {}

  template <Number T>
  void operator()(const std::string& name, T& value) {
    const Stored<T> stored = static_cast<Stored<T>>(value);
    file_.write(name, &stored, 1);
  }
  template <Number T>
  void operator()(const std::string& name, std::vector<T>& values) {
    file_.write(name, values.data(), values.size());
  }
  template <FixedEigen T>
  void operator()(const std::string& name, std::vector<T>& values) {
    file_.write(name, values.empty() ? nullptr : values.front().data(), values.size(),
                T::SizeAtCompileTime);
  }
  template <std::size_t N>
  void operator()(const std::string& name, std::array<double, N>& values) {
    file_.write(name, values.data(), N);
  }
  template <std::size_t N>
  void operator()(const std::string& name, std::vector<std::array<double, N>>& values) {
    file_.write(name, values.empty() ? nullptr : values.front().data(), values.size(), N);
  }
  void operator()(const std::string& name, std::string& text) { file_.write_string(name, text); }
  // A field that checkpoints of earlier versions lack (CheckpointReader::optional).
  template <class T>
  void optional(const std::string& name, T& value) {
    (*this)(name, value);
  }

 private:
  io::Hdf5File& file_;
};

class CheckpointReader {
 public:
  static constexpr bool kReading = true;
  explicit CheckpointReader(const io::Hdf5File& file) : file_(file) {}

  template <Number T>
  void operator()(const std::string& name, T& value) {
    Stored<T> stored{};
    file_.read(name, &stored, 1);
    value = static_cast<T>(stored);
  }
  // A vector takes the checkpoint's length.
  template <Number T>
  void operator()(const std::string& name, std::vector<T>& values) {
    values.resize(file_.rows(name));
    file_.read(name, values.data(), values.size());
  }
  template <FixedEigen T>
  void operator()(const std::string& name, std::vector<T>& values) {
    values.resize(file_.rows(name));
    file_.read(name, values.empty() ? nullptr : values.front().data(), values.size(),
               T::SizeAtCompileTime);
  }
  template <std::size_t N>
  void operator()(const std::string& name, std::array<double, N>& values) {
    file_.read(name, values.data(), N);
  }
  template <std::size_t N>
  void operator()(const std::string& name, std::vector<std::array<double, N>>& values) {
    values.resize(file_.rows(name));
    file_.read(name, values.empty() ? nullptr : values.front().data(), values.size(), N);
  }
  void operator()(const std::string& name, std::string& text) { text = file_.read_string(name); }
  // Read if the checkpoint has it; else `value` keeps what it holds.
  template <class T>
  void optional(const std::string& name, T& value) {
    if (file_.has(name)) (*this)(name, value);
  }

 private:
  const io::Hdf5File& file_;
};

// The three axes of a per-point vector field, as NAME_x, NAME_y, NAME_z.
template <class Archive, class T>
void axes(Archive& archive, const std::string& name, std::array<std::vector<T>, 3>& field) {
  archive(name + "_x", field[0]);
  archive(name + "_y", field[1]);
  archive(name + "_z", field[2]);
}

}  // namespace coldspray::checkpoint
