#include "table.hpp"

#include <fstream>
#include <sstream>
#include <stdexcept>

namespace coldspray::testing {

std::size_t Table::column(const std::string& name) const {
  for (std::size_t i = 0; i < header.size(); ++i)
    if (header[i] == name) return i;
  throw std::runtime_error("no column " + name);
}

std::vector<double> Table::values(const std::string& name) const {
  const std::size_t c = column(name);
  std::vector<double> out;
  for (const auto& r : rows) out.push_back(r[c]);
  return out;
}

Table read_table(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw std::runtime_error("cannot read " + path);
  Table t;
  std::string line, cell;
  std::getline(in, line);
  std::stringstream head(line);
  while (std::getline(head, cell, ',')) t.header.push_back(cell);
  while (std::getline(in, line)) {
    std::stringstream row(line);
    std::vector<double> values;
    while (std::getline(row, cell, ',')) values.push_back(std::stod(cell));
    t.rows.push_back(std::move(values));
  }
  return t;
}

}  // namespace coldspray::testing
