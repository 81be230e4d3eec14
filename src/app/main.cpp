// argine command-line entry (placeholder until the app room lands).
#include <cstdio>

#include "argine/core/Version.hpp"

int main() {
  std::printf("argine %s\n", argine::kVersion);
  return 0;
}
