#include "case/field_rules.hpp"

#include <cmath>

#include "case/shortest_number.hpp"

namespace coldspray::case_file {

bool Range::contains(double value) const {
  const bool above = min_open ? value > min : value >= min;
  const bool below = max_open ? value < max : value <= max;
  return above && below;
}

std::string Range::describe() const {
  if (std::isinf(max)) return (min_open ? "> " : ">= ") + shortest_text(min);
  return std::string("in ") + (min_open ? "(" : "[") + shortest_text(min) + ", " +
         shortest_text(max) + (max_open ? ")" : "]");
}

}  // namespace coldspray::case_file
