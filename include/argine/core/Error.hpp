#pragma once
/// @file Error.hpp
/// Errors argine reports to users. Input errors name the key path or file and what is
/// expected, and map to exit code 2; runtime faults (instability) map to exit code 3.

#include <stdexcept>
#include <string>
#include <vector>

namespace argine {

/// A problem with user input (deck, mesh, time series). Raised before a run starts.
/// `where` is a key path such as "Stages/flood/Boundary Conditions/river/Total Head"
/// or a file name; `what()` gives the full message "where: problem".
class InputError : public std::runtime_error {
 public:
  InputError(std::string where, const std::string& problem)
      : std::runtime_error(where + ": " + problem), where_(std::move(where)) {}
  const std::string& where() const { return where_; }

 private:
  std::string where_;
};

/// A run that cannot go on (non-finite values, energy blow-up). The message says when and
/// where; the last good output is kept.
class RunError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

/// Exit codes of the `argine` command.
inline constexpr int kExitOk = 0;
inline constexpr int kExitInputError = 2;
inline constexpr int kExitRunError = 3;

/// Levenshtein distance between two strings (case-insensitive), for "did you mean".
int editDistance(const std::string& a, const std::string& b);

/// The candidate closest to `word`, or "" when none is reasonably close.
std::string closestMatch(const std::string& word, const std::vector<std::string>& candidates);

}  // namespace argine
