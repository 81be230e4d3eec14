#pragma once
/// @file CommandLine.hpp
/// The few options every verification driver takes, as `--name value` pairs.

#include <map>
#include <string>
#include <vector>

namespace argine::verification {

/// `--name value` options; a bare `--name` is stored with the value "true".
class CommandLine {
 public:
  /// Parses argv[1..]; std::invalid_argument for a word that is not an option or a value,
  /// or an option not in `known`.
  CommandLine(int argc, char** argv, const std::vector<std::string>& known);

  bool has(const std::string& name) const { return values_.count(name) != 0; }
  /// The value of --name, or `fallback` when absent.
  std::string text(const std::string& name, const std::string& fallback) const;
  /// The value of --name as a number.
  double number(const std::string& name, double fallback) const;
  /// The value of --name as a comma-separated list of integers ("10,20,40").
  std::vector<int> integers(const std::string& name, const std::vector<int>& fallback) const;
  /// The value of --name as a comma-separated list of numbers.
  std::vector<double> numbers(const std::string& name, const std::vector<double>& fallback) const;
  /// The value of --name as a comma-separated list of words (none when absent).
  std::vector<std::string> texts(const std::string& name) const;

 private:
  std::map<std::string, std::string> values_;
};

}  // namespace argine::verification
