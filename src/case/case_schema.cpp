#include "case/case_schema.hpp"

namespace coldspray::case_file {

namespace {
constexpr std::string_view kBodyPrefix = "body:";
}

void ContactNormalText::parse(std::string_view text, MpmContact& contact) const {
  if (text == "max-gradient") {
    contact.normal = ContactNormal::MaxGradient;
    contact.normal_body.clear();
  } else if (text == "highest-id") {
    contact.normal = ContactNormal::HighestId;
    contact.normal_body.clear();
  } else if (text == "average-gradient") {
    contact.normal = ContactNormal::AverageGradient;
    contact.normal_body.clear();
  } else if (text.starts_with(kBodyPrefix) && text.size() > kBodyPrefix.size()) {
    contact.normal = ContactNormal::Body;
    contact.normal_body = text.substr(kBodyPrefix.size());
  } else {
    constexpr std::array<std::string_view, 4> kForms{"max-gradient", "average-gradient",
                                                     "highest-id", "body:NAME"};
    throw BadValue(unknown_word("contact normal", text, kForms));
  }
}

std::string ContactNormalText::format(const MpmContact& contact) const {
  switch (contact.normal) {
    case ContactNormal::MaxGradient:
      return "max-gradient";
    case ContactNormal::HighestId:
      return "highest-id";
    case ContactNormal::AverageGradient:
      return "average-gradient";
    case ContactNormal::Body:
      return std::string(kBodyPrefix) + contact.normal_body;
  }
  throw std::logic_error("unnamed contact normal");
}

bool is_folder_name(const std::string& name) {
  return !name.empty() && name != "." && name != ".." &&
         name.find_first_of("/\\") == std::string::npos;
}

}  // namespace coldspray::case_file
