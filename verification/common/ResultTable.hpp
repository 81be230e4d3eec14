#pragma once
/// @file ResultTable.hpp
/// Rows of numbers with named columns: printed as an aligned table and written as CSV.

#include <iosfwd>
#include <string>
#include <vector>

namespace argine::verification {

/// A table whose cells are text or numbers (numbers are written with 6 significant digits
/// in the printed table and in full precision in the CSV).
class ResultTable {
 public:
  explicit ResultTable(std::vector<std::string> columns);

  /// Starts a new row.
  ResultTable& row();
  /// Appends a cell to the current row.
  ResultTable& add(const std::string& text);
  ResultTable& add(double value);
  ResultTable& add(long value);
  ResultTable& add(int value) { return add(static_cast<long>(value)); }

  /// Aligned columns with a header line.
  void print(std::ostream& out) const;
  /// CSV with a header line; std::runtime_error when the file cannot be written.
  void writeCsv(const std::string& path) const;

  std::size_t rows() const { return printed_.size(); }

 private:
  std::vector<std::string> columns_;
  std::vector<std::vector<std::string>> printed_;  ///< cells as printed
  std::vector<std::vector<std::string>> exact_;    ///< cells as written to CSV
};

/// Joins a directory and a file name ("" = current directory).
std::string pathIn(const std::string& directory, const std::string& file);

}  // namespace argine::verification
