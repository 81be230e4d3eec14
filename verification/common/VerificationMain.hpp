#pragma once
/// @file VerificationMain.hpp
/// The process frame of a verification driver: MPI and Kokkos for the whole run, and every
/// error turned into a message and an exit code CTest understands.

#include <functional>

namespace argine::verification {

/// Exit code of a driver whose errors exceed a bound of doc/verification.md.
inline constexpr int kExitBoundExceeded = 1;
/// Exit code of a driver that could not run (bad deck, unstable run, bad option).
inline constexpr int kExitCannotRun = 4;

/// Initialises MPI and Kokkos, calls `body` and returns its exit code; an exception from
/// `body` is printed and gives kExitCannotRun.
int runVerification(int argc, char** argv, const std::function<int(int, char**)>& body);

}  // namespace argine::verification
