// The keys a struct's schema declares, in order: what a YAML map of that struct may contain.
#pragma once

#include <string_view>
#include <vector>

namespace coldspray::case_file {

class KeyList {
 public:
  template <class... Args>
  void scalar(std::string_view key, Args&&...) {
    keys_.push_back(key);
  }
  template <class... Args>
  void scalars(std::string_view key, Args&&...) {
    keys_.push_back(key);
  }
  template <class... Args>
  void table(std::string_view key, Args&&...) {
    keys_.push_back(key);
  }
  template <class... Args>
  void quantity(std::string_view key, Args&&...) {
    keys_.push_back(key);
  }
  template <class... Args>
  void vector(std::string_view key, Args&&...) {
    keys_.push_back(key);
  }
  template <class... Args>
  void section(std::string_view key, Args&&...) {
    keys_.push_back(key);
  }
  template <class... Args>
  void section_either(std::string_view key, Args&&...) {
    keys_.push_back(key);
  }
  template <class... Args>
  void variant(std::string_view key, Args&&...) {
    keys_.push_back(key);
  }
  template <class... Args>
  void list(std::string_view key, Args&&...) {
    keys_.push_back(key);
  }
  template <class... Args>
  void materials(std::string_view key, Args&&...) {
    keys_.push_back(key);
  }
  template <class... Args>
  void check(Args&&...) {}

  const std::vector<std::string_view>& keys() const { return keys_; }

 private:
  std::vector<std::string_view> keys_;
};

template <class T>
std::vector<std::string_view> keys_of(T& target) {
  KeyList list;
  fields(list, target);
  return list.keys();
}

}  // namespace coldspray::case_file
