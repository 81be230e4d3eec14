#include "CommandLine.hpp"

#include <algorithm>
#include <sstream>
#include <stdexcept>

namespace argine::verification {

namespace {

std::vector<std::string> splitCommas(const std::string& text) {
  std::vector<std::string> parts;
  std::stringstream stream(text);
  std::string part;
  while (std::getline(stream, part, ','))
    if (!part.empty()) parts.push_back(part);
  return parts;
}

}  // namespace

CommandLine::CommandLine(int argc, char** argv, const std::vector<std::string>& known) {
  for (int i = 1; i < argc; ++i) {
    const std::string word = argv[i];
    if (word.rfind("--", 0) != 0) throw std::invalid_argument("unexpected argument '" + word + "'");
    const std::string name = word.substr(2);
    if (std::find(known.begin(), known.end(), name) == known.end()) {
      std::string list;
      for (const auto& option : known) list += " --" + option;
      throw std::invalid_argument("unknown option '" + word + "'; known:" + list);
    }
    const bool has_value = i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0;
    values_[name] = has_value ? argv[++i] : "true";
  }
}

std::string CommandLine::text(const std::string& name, const std::string& fallback) const {
  const auto found = values_.find(name);
  return found == values_.end() ? fallback : found->second;
}

double CommandLine::number(const std::string& name, double fallback) const {
  return has(name) ? std::stod(text(name, "")) : fallback;
}

std::vector<int> CommandLine::integers(const std::string& name,
                                       const std::vector<int>& fallback) const {
  if (!has(name)) return fallback;
  std::vector<int> values;
  for (const auto& part : splitCommas(text(name, ""))) values.push_back(std::stoi(part));
  return values;
}

std::vector<double> CommandLine::numbers(const std::string& name,
                                         const std::vector<double>& fallback) const {
  if (!has(name)) return fallback;
  std::vector<double> values;
  for (const auto& part : splitCommas(text(name, ""))) values.push_back(std::stod(part));
  return values;
}

std::vector<std::string> CommandLine::texts(const std::string& name) const {
  return has(name) ? splitCommas(text(name, "")) : std::vector<std::string>{};
}

}  // namespace argine::verification
