// The names of a variant's alternatives, each alternative's `static constexpr std::string_view
// kName`, in the variant's order: a list of model names derived from the model variant cannot
// fall out of step with it (the schema matches a name to the alternative at its position).
#pragma once

#include <array>
#include <cstddef>
#include <string_view>
#include <utility>
#include <variant>

namespace coldspray {

namespace detail {
template <class Variant, std::size_t... k>
constexpr std::array<std::string_view, sizeof...(k)> variant_names(std::index_sequence<k...>) {
  return {std::variant_alternative_t<k, Variant>::kName...};
}
}  // namespace detail

template <class Variant>
constexpr std::array<std::string_view, std::variant_size_v<Variant>> variant_names() {
  return detail::variant_names<Variant>(std::make_index_sequence<std::variant_size_v<Variant>>{});
}

}  // namespace coldspray
