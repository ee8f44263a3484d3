#include "io/csv_columns.hpp"

#include <algorithm>
#include <fstream>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace coldspray::io {
namespace {

std::vector<std::string> cells(const std::string& line) {
  std::vector<std::string> out;
  std::istringstream in(line);
  for (std::string cell; std::getline(in, cell, ',');) out.push_back(cell);
  return out;
}

double number(const std::string& cell) {
  try {
    std::size_t used = 0;
    const double x = std::stod(cell, &used);
    return used == cell.size() ? x : std::numeric_limits<double>::quiet_NaN();
  } catch (const std::exception&) {
    return std::numeric_limits<double>::quiet_NaN();
  }
}

}  // namespace

std::vector<std::vector<double>> read_csv_columns(const std::filesystem::path& file,
                                                  const std::vector<std::string>& names) {
  std::ifstream in(file);
  std::string line;
  if (!in || !std::getline(in, line)) throw std::runtime_error(file.string() + ": cannot read");
  const std::vector<std::string> header = cells(line);
  std::vector<std::size_t> at;
  for (const std::string& name : names) {
    const auto it = std::find(header.begin(), header.end(), name);
    if (it == header.end()) throw std::runtime_error(file.string() + ": no column '" + name + "'");
    at.push_back(static_cast<std::size_t>(it - header.begin()));
  }
  std::vector<std::vector<double>> columns(names.size());
  while (std::getline(in, line)) {
    const std::vector<std::string> row = cells(line);
    for (std::size_t k = 0; k < at.size(); ++k)
      columns[k].push_back(at[k] < row.size() ? number(row[at[k]])
                                              : std::numeric_limits<double>::quiet_NaN());
  }
  return columns;
}

}  // namespace coldspray::io
