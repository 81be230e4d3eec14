#pragma once
// Shared by the fuzz targets: Kokkos started once, a private working directory, and the
// rule every target checks: bad input may only end in an argine::InputError that names
// where the problem is. Any other exception escapes to libFuzzer, which reports it as a
// crash ("uncaught exception") with the input that caused it.

#include <unistd.h>

#include <Kokkos_Core.hpp>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "argine/core/Error.hpp"

namespace argine::fuzz {

/// Starts Kokkos (the mesh lives in Kokkos Views) and finalises it at exit.
inline void startKokkos() {
  if (Kokkos::is_initialized()) return;
  Kokkos::InitArguments arguments;
  arguments.disable_warnings = true;
  Kokkos::initialize(arguments);
  std::atexit([] { Kokkos::finalize(); });
}

/// A working directory for this fuzzer process: $ARGINE_FUZZ_WORKDIR or one under /tmp.
inline std::filesystem::path workDirectory(const std::string& target) {
  const char* chosen = std::getenv("ARGINE_FUZZ_WORKDIR");
  const std::filesystem::path directory =
      chosen ? std::filesystem::path(chosen)
             : std::filesystem::temp_directory_path() /
                   ("argine_fuzz_" + target + "_" + std::to_string(getpid()));
  std::filesystem::create_directories(directory);
  return directory;
}

/// Writes `size` bytes to `path` (overwriting it).
inline void writeBytes(const std::filesystem::path& path, const unsigned char* data,
                       std::size_t size) {
  std::ofstream file(path, std::ios::binary | std::ios::trunc);
  file.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
}

/// An InputError must say where (a key path or a file) and what.
inline void checkInputError(const InputError& error) {
  const std::string message = error.what();
  if (error.where().empty() || message.size() <= error.where().size() + 2) {
    std::fprintf(stderr, "InputError without a place or a problem: '%s'\n", message.c_str());
    std::abort();
  }
}

}  // namespace argine::fuzz
