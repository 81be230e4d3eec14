#pragma once
// The rows of a CSV file the run wrote (header skipped), every field as a number: what tests
// compare against hand values.

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace argine {

inline std::vector<std::vector<double>> readCsvRows(const std::string& path) {
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);  // header
  std::vector<std::vector<double>> rows;
  while (std::getline(in, line)) {
    std::vector<double> row;
    std::stringstream fields(line);
    std::string field;
    while (std::getline(fields, field, ',')) row.push_back(std::stod(field));
    rows.push_back(row);
  }
  return rows;
}

}  // namespace argine
