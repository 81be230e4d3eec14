#include "argine/output/CsvWriter.hpp"

#include <charconv>
#include <filesystem>
#include <stdexcept>
#include <system_error>

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

std::string headerLine(const std::vector<std::string>& columns) {
  std::string line;
  for (std::size_t c = 0; c < columns.size(); ++c)
    line += (c > 0 ? "," : "") + csvField(columns[c]);
  return line + '\n';
}
}  // namespace

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns)
    : path_(path), columns_(columns) {
  if (columns_.empty()) throw std::invalid_argument(path + ": a CSV file needs columns");
  out_.open(path, std::ios::out | std::ios::trunc);
  if (!out_) throw InputError(path, "cannot open the CSV file for writing");
  const std::string header = headerLine(columns_);
  out_ << header << std::flush;
  bytes_ = header.size();
}

CsvWriter::CsvWriter(const std::string& path, const std::vector<std::string>& columns,
                     CsvResume resume)
    : path_(path), columns_(columns) {
  if (columns_.empty()) throw std::invalid_argument(path + ": a CSV file needs columns");
  namespace fs = std::filesystem;
  std::error_code error;
  const std::uintmax_t size = fs::file_size(path, error);
  if (error)
    throw InputError(
        path, "cannot continue the CSV file of the checkpointed run (" + error.message() + ")");
  if (size < resume.bytes)
    throw InputError(path, "holds " + std::to_string(size) + " bytes, fewer than the " +
                               std::to_string(resume.bytes) +
                               " the checkpoint recorded: not the checkpointed run's file");
  const std::string header = headerLine(columns_);
  {
    std::ifstream in(path, std::ios::binary);
    std::string first(header.size(), '\0');
    in.read(first.data(), static_cast<std::streamsize>(first.size()));
    if (resume.bytes < header.size() || first != header)
      throw InputError(path,
                       "its header is not the one this run writes: not the checkpointed "
                       "run's file");
  }
  fs::resize_file(path, resume.bytes, error);
  if (error) throw InputError(path, "cannot truncate the CSV file (" + error.message() + ")");
  out_.open(path, std::ios::out | std::ios::app);
  if (!out_) throw InputError(path, "cannot open the CSV file for appending");
  bytes_ = resume.bytes;
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
  bytes_ += row.size();
}

}  // namespace argine
