// Uses installed argine headers and libraries: a suggestion and the version string.
#include <cstdio>

#include "argine/core/Error.hpp"
#include "argine/core/Version.hpp"

int main() {
  const std::string suggestion = argine::closestMatch("Duraton (s)", {"Duration (s)", "Solver"});
  std::printf("argine %s suggests '%s'\n", argine::kVersion, suggestion.c_str());
  return suggestion == "Duration (s)" ? 0 : 1;
}
