// The contact laws between points of different bodies (docs/pd.md): the short-range repulsion
// and the PD paper's contact models 1 and 2. Each law is one file beside this one, a struct with
//  - kName, its name in the case's contact.peridynamics.model (case_file::kContactModelNames),
//  - kAdhesive: whether it can hold two bodies together,
//  - reach, m: it exerts no force on a pair farther apart,
//  - make(ContactLawInputs): the law between two bodies, from the case,
//  - force(pair, r, |r|): the force density on the pair's point i, N/m^3, and
//  - holds(pair): whether the pair holds the two bodies together (bodies::Points::bonded_to);
// the loops that apply them are pd/forces.cpp's. A new law is its file and one entry below, in
// the order of case_file::ContactModel (registry.cpp checks the names and the order).
#pragma once

#include <algorithm>
#include <variant>
#include <vector>

#include "pd/laws/interface_bonds.hpp"
#include "pd/laws/lennard_jones.hpp"
#include "pd/laws/repulsive.hpp"

namespace coldspray::pd {

using ContactLaw = std::variant<Repulsive, LennardJones, InterfaceBonds>;

// The case's contact law between two bodies.
ContactLaw make_contact_law(const ContactLawInputs& in);

// The largest reach of the laws, m: the contact list's (pd/contact.hpp).
inline double largest_reach(const std::vector<ContactLaw>& laws) {
  double reach = 0.0;
  for (const ContactLaw& law : laws)
    reach = std::max(reach, std::visit([](const auto& l) { return l.reach; }, law));
  return reach;
}

// Whether some law is one that can hold two bodies together: the verdict then reads the area
// they hold (bodies::Points::bonded_to).
inline bool any_adhesive(const std::vector<ContactLaw>& laws) {
  return std::any_of(laws.begin(), laws.end(), [](const ContactLaw& law) {
    return std::visit([](const auto& l) { return l.kAdhesive; }, law);
  });
}

}  // namespace coldspray::pd
