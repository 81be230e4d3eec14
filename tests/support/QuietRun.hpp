#pragma once
// Whole-deck runs in the tests: the output into a fresh directory, without progress lines.

#include <filesystem>

#include "argine/simulation/Simulation.hpp"

namespace argine::test {

/// RunOptions that write quietly into `dir`, emptied (or made) first.
inline RunOptions quietRunIn(const std::filesystem::path& dir) {
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  RunOptions options;
  options.output_directory = dir.string();
  options.quiet = true;
  return options;
}

}  // namespace argine::test
