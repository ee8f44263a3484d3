#include "pd/laws/contact_pair.hpp"

#include <cmath>
#include <numbers>

namespace coldspray::pd {

double ContactLawInputs::micromodulus() const {
  return 18.0 * bulk_modulus / (std::numbers::pi * std::pow(horizon, 4));
}

}  // namespace coldspray::pd
