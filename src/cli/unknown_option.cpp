#include "cli/unknown_option.hpp"

#include <algorithm>
#include <array>
#include <string_view>
#include <utility>
#include <vector>

#include "case/suggest.hpp"

namespace coldspray::cli {

namespace {

// Words a new user reaches for, and the option that means it, where spelling is no guide.
constexpr std::array<std::pair<std::string_view, std::string_view>, 7> kSynonyms{{
    {"--speed", "--velocity"},
    {"--size", "--diameter"},
    {"--radius", "--diameter"},
    {"--time", "--end-time"},
    {"--duration", "--end-time"},
    {"--output", "--out"},
    {"--cell", "--grid"},
}};

std::optional<std::string> message_for(const CLI::App& sub) {
  for (const std::string& arg : sub.remaining()) {
    // CLI11 lists an empty leftover as nothing: "The following argument was not expected: ".
    if (arg.empty()) return "an empty argument ('') was not expected";
    if (arg.size() < 2 || arg[0] != '-') continue;
    const std::string name = arg.substr(0, arg.find('='));
    std::vector<std::string> names;
    for (const CLI::Option* o : sub.get_options())
      for (const std::string& l : o->get_lnames()) names.push_back("--" + l);
    const std::vector<std::string_view> candidates(names.begin(), names.end());
    std::optional<std::string_view> meant = case_file::closest(name, candidates);
    for (const auto& [word, option] : kSynonyms)
      if (!meant && name == word && std::find(names.begin(), names.end(), option) != names.end())
        meant = option;
    std::string message = "unknown option " + name;
    if (meant) return message + "; did you mean " + std::string(*meant) + "?";
    const std::string command = sub.get_parent() ? " " + sub.get_name() : "";
    return message + " (coldspray" + command + " --help lists the options)";
  }
  return std::nullopt;
}

}  // namespace

std::optional<std::string> unknown_option_message(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands())
    if (auto message = message_for(*sub)) return message;
  return message_for(app);
}

}  // namespace coldspray::cli
