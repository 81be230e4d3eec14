#pragma once
/// @file CsvWriter.hpp
/// A CSV time series (diagnostics, probes): a header line of column names once, then one
/// row of numbers per call, flushed at once so a killed run keeps every row written.
/// Numbers are written in the shortest form that reads back to the same double.

#include <fstream>
#include <string>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

class CsvWriter {
 public:
  /// Creates (or truncates) `path` and writes the header. Throws InputError naming the file
  /// when it cannot be opened, std::invalid_argument for no columns.
  CsvWriter(const std::string& path, const std::vector<std::string>& columns);

  /// Appends one row; throws std::invalid_argument unless it has one value per column.
  void writeRow(const std::vector<Real>& values);

  const std::string& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }

 private:
  std::string path_;
  std::vector<std::string> columns_;
  std::ofstream out_;
};

}  // namespace argine
