#include "pd/laws/repulsive.hpp"

namespace coldspray::pd {

Repulsive Repulsive::make(const ContactLawInputs& in) {
  Repulsive law;
  law.contact = {in.settings.contact_distance * in.spacing, in.settings.contact_initial_fraction};
  law.reach = law.contact.distance;
  law.stiffness = in.settings.contact_stiffness * in.micromodulus() / in.horizon;
  return law;
}

}  // namespace coldspray::pd
