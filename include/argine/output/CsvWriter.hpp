#pragma once
/// @file CsvWriter.hpp
/// A CSV time series (diagnostics, probes): a header line of column names once, then one
/// row of numbers per call, flushed at once so a killed run keeps every row written.
/// Numbers are written in the shortest form that reads back to the same double.

#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

/// Where a restarted run continues a CSV file: after its first `bytes` bytes (the size a
/// checkpoint recorded); rows a killed run wrote after the checkpoint are dropped.
struct CsvResume {
  std::uintmax_t bytes = 0;
};

class CsvWriter {
 public:
  /// Creates (or truncates) `path` and writes the header. Throws InputError naming the file
  /// when it cannot be opened, std::invalid_argument for no columns.
  CsvWriter(const std::string& path, const std::vector<std::string>& columns);

  /// Reopens `path`, written by the checkpointed run with the same `columns`, truncates it to
  /// `resume.bytes` and appends from there. Throws InputError naming the file when it is
  /// missing, shorter than that, or has another header.
  CsvWriter(const std::string& path, const std::vector<std::string>& columns, CsvResume resume);

  /// Appends one row; throws std::invalid_argument unless it has one value per column.
  void writeRow(const std::vector<Real>& values);

  const std::string& path() const { return path_; }
  const std::vector<std::string>& columns() const { return columns_; }
  /// Bytes in the file so far (header and rows, all flushed).
  std::uintmax_t bytes() const { return bytes_; }

 private:
  std::string path_;
  std::vector<std::string> columns_;
  std::ofstream out_;
  std::uintmax_t bytes_ = 0;
};

}  // namespace argine
