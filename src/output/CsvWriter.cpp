#include "argine/output/CsvWriter.hpp"

#include <charconv>
#include <stdexcept>

#include "argine/core/Error.hpp"

namespace argine {

namespace {
// A column name as a CSV field: quoted (with doubled quotes) only when it needs to be.
std::string csvField(const std::string& text) {
  if (text.find_first_of(",\"\n\r") == std::string::npos) return text;
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"') quoted += '"';
    quoted += c;
  }
  return quoted + "\"";
}
}  // namespace

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns)
    : path_(path), columns_(columns) {
  if (columns_.empty()) throw std::invalid_argument(path + ": a CSV file needs columns");
  out_.open(path, std::ios::out | std::ios::trunc);
  if (!out_) throw InputError(path, "cannot open the CSV file for writing");
  for (std::size_t c = 0; c < columns_.size(); ++c)
    out_ << (c > 0 ? "," : "") << csvField(columns_[c]);
  out_ << '\n' << std::flush;
}

void CsvWriter::writeRow(const std::vector<Real>& values) {
  if (values.size() != columns_.size())
    throw std::invalid_argument(path_ + ": row of " + std::to_string(values.size()) +
                                " values for " + std::to_string(columns_.size()) + " columns");
  std::string row;
  char buffer[32];
  for (std::size_t c = 0; c < values.size(); ++c) {
    if (c > 0) row += ',';
    const auto result = std::to_chars(buffer, buffer + sizeof(buffer), values[c]);
    row.append(buffer, result.ptr);
  }
  row += '\n';
  out_ << row << std::flush;
  if (!out_) throw RunError(path_ + ": writing a CSV row failed");
}

}  // namespace argine
