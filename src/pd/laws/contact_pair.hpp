// What the contact laws (pd/laws/registry.hpp) share: the candidate pair a law acts on, the
// contact distance that two of them start from, and what a law between two bodies is built from.
// The loops that find the pairs and apply the laws are pd/contact.hpp and pd/forces.cpp; a law
// only says, for one pair, its force density and whether it holds the pair together (after
// CabanaPD, which keeps the point-wise force functor apart from the neighbour loops).
#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstddef>

#include "case/case.hpp"
#include "materials/material.hpp"
#include "pd/contact.hpp"
#include "pd/neighbours.hpp"

namespace coldspray::pd {

// The `candidate`-th entry of the contact list: real point i and point j (real or ghost) of
// another body.
struct ContactPair {
  const Neighbours& N;
  const ContactList& list;
  std::size_t i = 0;
  std::size_t j = 0;
  std::size_t candidate = 0;
};

// The pair's contact distance d = min(distance, initial_fraction |X_i - X_j|) (pd/contact.hpp):
// where the repulsion starts, and contact model 2's rest length.
struct ContactDistance {
  double distance = 0.0;          // m
  double initial_fraction = 0.0;  // of the pair's distance at t = 0
  double of(const ContactPair& p) const {
    return std::min(distance, initial_fraction * (p.N.reference[p.i] - p.N.reference[p.j]).norm());
  }
};

// What the law between bodies a and b is built from (pd/setup.cpp): the case's contact section
// and peridynamics settings, the two materials, and the lengths and modulus the law is the same
// both ways with.
struct ContactLawInputs {
  const case_file::Case& c;
  const case_file::Peridynamics& settings;
  const materials::Material& a;
  const materials::Material& b;
  double horizon = 0.0;       // delta, the larger of the two bodies', m
  double bulk_modulus = 0.0;  // K, the softer material's, Pa
  double spacing = 0.0;       // the finer body's, m
  // c = 18 K / (pi delta^4), the bond micromodulus (Silling and Askari 2005), N/m^6.
  double micromodulus() const;
};

}  // namespace coldspray::pd
