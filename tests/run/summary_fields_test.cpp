// summary.json's declared fields: the writer emits them in declared order, leaves out absent
// ones, and docs/outputs.md's table lists the same fields with the same units.
#include <gtest/gtest.h>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

#include "io/output_schema.hpp"
#include "run/summary.hpp"

namespace {

struct Shot {
  double speed = 0.0;
  std::string name;
  bool has_name = false;
};

TEST(OutputSchema, WritesTheDeclaredFieldsInOrderAndLeavesOutAbsentOnes) {
  using Json = nlohmann::ordered_json;
  const coldspray::io::OutputFields<Shot> fields = {
      {"speed", "m/s", [](const Shot& s) { return Json(s.speed); }},
      {"name", "-",
       [](const Shot& s) { return s.has_name ? Json(s.name) : coldspray::io::absent_field(); }},
      {"length", "m", [](const Shot&) { return Json(2.5); },
       [](const Shot&) { return std::string("horizon"); }}};
  EXPECT_EQ(coldspray::io::write_fields(fields, Shot{810.0, "al", true}).dump(),
            R"({"speed":810.0,"name":"al","horizon":2.5})");
  EXPECT_EQ(coldspray::io::write_fields(fields, Shot{700.0, "", false}).dump(),
            R"({"speed":700.0,"horizon":2.5})");
}

TEST(SummaryFields, DocsTableListsTheDeclaredFieldsAndUnits) {
  std::ifstream doc(std::string(COLDSPRAY_SOURCE_DIR) + "/docs/outputs.md");
  ASSERT_TRUE(doc) << "docs/outputs.md";
  std::vector<std::pair<std::string, std::string>> table;
  bool in_table = false;
  for (std::string line; std::getline(doc, line);) {
    if (line == "<!-- summary.json fields -->") in_table = true;
    if (line == "<!-- end summary.json fields -->") break;
    if (!in_table || line.rfind("| ", 0) != 0 || line == "| field | unit |" ||
        line.rfind("| ---", 0) == 0)
      continue;
    const std::size_t bar = line.find(" | ", 2);
    table.emplace_back(line.substr(2, bar - 2), line.substr(bar + 3, line.size() - bar - 5));
  }
  EXPECT_EQ(table, coldspray::run::summary_field_units());
}

}  // namespace
