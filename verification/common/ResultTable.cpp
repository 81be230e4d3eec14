#include "ResultTable.hpp"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <ostream>
#include <sstream>
#include <stdexcept>

namespace argine::verification {

ResultTable::ResultTable(std::vector<std::string> columns) : columns_(std::move(columns)) {}

ResultTable& ResultTable::row() {
  printed_.emplace_back();
  exact_.emplace_back();
  return *this;
}

ResultTable& ResultTable::add(const std::string& text) {
  if (printed_.empty()) row();
  printed_.back().push_back(text);
  exact_.back().push_back(text);
  return *this;
}

ResultTable& ResultTable::add(double value) {
  if (printed_.empty()) row();
  std::ostringstream shortText, longText;
  shortText << std::setprecision(6) << value;
  longText << std::setprecision(17) << value;
  printed_.back().push_back(shortText.str());
  exact_.back().push_back(longText.str());
  return *this;
}

ResultTable& ResultTable::add(long value) {
  if (printed_.empty()) row();
  printed_.back().push_back(std::to_string(value));
  exact_.back().push_back(std::to_string(value));
  return *this;
}

void ResultTable::print(std::ostream& out) const {
  std::vector<std::size_t> width(columns_.size());
  for (std::size_t c = 0; c < columns_.size(); ++c) width[c] = columns_[c].size();
  for (const auto& cells : printed_)
    for (std::size_t c = 0; c < cells.size() && c < width.size(); ++c)
      width[c] = std::max(width[c], cells[c].size());
  auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size() && c < width.size(); ++c)
      out << (c ? "  " : "") << std::setw(static_cast<int>(width[c])) << cells[c];
    out << "\n";
  };
  line(columns_);
  for (const auto& cells : printed_) line(cells);
}

void ResultTable::writeCsv(const std::string& path) const {
  std::ofstream file(path);
  if (!file) throw std::runtime_error("cannot write " + path);
  auto line = [&](const std::vector<std::string>& cells) {
    for (std::size_t c = 0; c < cells.size(); ++c) file << (c ? "," : "") << cells[c];
    file << "\n";
  };
  line(columns_);
  for (const auto& cells : exact_) line(cells);
  if (!file) throw std::runtime_error("error writing " + path);
}

std::string pathIn(const std::string& directory, const std::string& file) {
  if (directory.empty()) return file;
  return directory.back() == '/' ? directory + file : directory + "/" + file;
}

}  // namespace argine::verification
