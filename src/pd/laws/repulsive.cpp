#include "pd/laws/repulsive.hpp"

namespace coldspray::pd {

Repulsive Repulsive::make(const ContactLawInputs& in) {
  Repulsive law;
  law.contact = {in.c.contact.peridynamics.repulsion.distance * in.spacing,
                 in.c.contact.peridynamics.repulsion.initial_fraction};
  law.reach = law.contact.distance;
  law.stiffness = in.c.contact.peridynamics.repulsion.stiffness * in.micromodulus() / in.horizon;
  return law;
}

}  // namespace coldspray::pd
