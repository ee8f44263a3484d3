// Reading back the numeric columns of a table this program wrote (history.csv and the like).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace coldspray::io {

// The named columns of a CSV file with a header row, in the order asked; a cell that is not a
// number reads as NaN. Throws std::runtime_error naming the file if it cannot be read or lacks a
// column.
std::vector<std::vector<double>> read_csv_columns(const std::filesystem::path& file,
                                                  const std::vector<std::string>& names);

}  // namespace coldspray::io
