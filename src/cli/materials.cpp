// `coldspray materials [NAME]`: list the built-in materials, or print one in full with sources.
#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

#include "case/load.hpp"
#include "cli/commands.hpp"

namespace coldspray::cli {

void add_materials(CLI::App& app) {
  auto name = std::make_shared<std::string>();
  auto* sub = app.add_subcommand(
      "materials", "List the built-in materials, or print one (NAME or CASE.yaml:NAME)");
  sub->add_option("name", *name, "Material to print");
  sub->callback([name] {
    if (!name->empty()) {
      case_file::print_material(case_file::resolve_material(*name), std::cout);
      return;
    }
    const std::vector<std::string> names = case_file::builtin_material_names();
    std::size_t width = 0;
    for (const auto& n : names) width = std::max(width, n.size());
    for (const auto& n : names)
      std::cout << fmt::format("{:{}} {}\n", n, width, case_file::builtin_material(n).description);
  });
}

}  // namespace coldspray::cli
