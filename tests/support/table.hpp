// Reading the CSV files coldspray writes (a header, then rows of numbers) in tests.
#pragma once

#include <string>
#include <vector>

namespace coldspray::testing {

struct Table {
  std::vector<std::string> header;
  std::vector<std::vector<double>> rows;
  std::size_t column(const std::string& name) const;
  std::vector<double> values(const std::string& name) const;
};

Table read_table(const std::string& path);

}  // namespace coldspray::testing
