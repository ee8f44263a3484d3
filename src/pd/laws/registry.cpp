#include "pd/laws/registry.hpp"

#include <cstddef>
#include <utility>

#include "case/case_schema.hpp"

namespace coldspray::pd {

namespace {

// case/ lies below pd/ and cannot name the laws: the case keeps its own list of model names,
// and this holds it to the laws', name for name and in order, so that the k-th ContactModel
// builds the k-th law.
template <std::size_t... k>
constexpr bool names_match(std::index_sequence<k...>) {
  constexpr auto& names = case_file::kContactModelNames.entries;
  return ((names[k].first == std::variant_alternative_t<k, ContactLaw>::kName &&
           static_cast<std::size_t>(names[k].second) == k) &&
          ...);
}
constexpr auto kLaws = std::make_index_sequence<std::variant_size_v<ContactLaw>>{};
static_assert(case_file::kContactModelNames.entries.size() == std::variant_size_v<ContactLaw>,
              "a contact model without a law, or a law without a name in the case");
static_assert(names_match(kLaws),
              "case_file::kContactModelNames must list the laws of ContactLaw by their kName, "
              "in order");

template <std::size_t k = 0>
ContactLaw make_law(std::size_t model, const ContactLawInputs& in) {
  if constexpr (k + 1 < std::variant_size_v<ContactLaw>)
    if (model != k) return make_law<k + 1>(model, in);
  return std::variant_alternative_t<k, ContactLaw>::make(in);
}

}  // namespace

ContactLaw make_contact_law(const ContactLawInputs& in) {
  return make_law(static_cast<std::size_t>(in.c.contact.peridynamics.model), in);
}

}  // namespace coldspray::pd
