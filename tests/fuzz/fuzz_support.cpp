#include "fuzz_support.hpp"

#include <algorithm>

#include "read_text.hpp"

namespace coldspray::fuzz {

namespace fs = std::filesystem;
using testing::read_text;

std::vector<std::string> yaml_texts(const std::vector<fs::path>& folders, bool recursive) {
  std::vector<std::string> out;
  const auto add = [&out](const fs::directory_entry& entry) {
    if (entry.path().extension() == ".yaml") out.push_back(read_text(entry.path()));
  };
  for (const fs::path& folder : folders) {
    if (recursive)
      std::for_each(fs::recursive_directory_iterator(folder), {}, add);
    else
      std::for_each(fs::directory_iterator(folder), {}, add);
  }
  std::sort(out.begin(), out.end());
  return out;
}

std::string_view Mutator::hostile_value() {
  std::size_t i = below(kHostileNumbers.size() + kHostileUnits.size() + kHostileYaml.size());
  if (i < kHostileNumbers.size()) return kHostileNumbers[i];
  i -= kHostileNumbers.size();
  if (i < kHostileUnits.size()) return kHostileUnits[i];
  return kHostileYaml[i - kHostileUnits.size()];
}

void Mutator::mutate(std::string& text) {
  const std::size_t at = below(text.size() + 1);
  switch (below(5)) {
    case 0:  // insert a token
      text.insert(at, pick(kTokens));
      break;
    case 1:  // delete a span
      text.erase(at, below(16) + 1);
      break;
    case 2: {  // duplicate a span
      const std::string span = text.substr(at, below(64) + 1);
      text.insert(below(text.size() + 1), span);
      break;
    }
    case 3:  // flip a byte
      if (at < text.size()) text[at] = static_cast<char>(random_() & 0xff);
      break;
    default:  // replace a number's digits by an extreme
      if (const std::size_t digit = text.find_first_of("0123456789", at);
          digit != std::string::npos)
        text.replace(digit, text.find_first_not_of("0123456789.e-", digit) - digit,
                     kTokens[kExtremes + below(5)]);
  }
}

}  // namespace coldspray::fuzz
