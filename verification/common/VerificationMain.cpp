#include "VerificationMain.hpp"

#include <mpi.h>

#include <exception>
#include <iostream>

#include <Kokkos_Core.hpp>

namespace argine::verification {

int runVerification(int argc, char** argv, const std::function<int(int, char**)>& body) {
  MPI_Init(&argc, &argv);
  int result = kExitCannotRun;
  {
    Kokkos::ScopeGuard kokkos(argc, argv);
    try {
      result = body(argc, argv);
    } catch (const std::exception& error) {
      std::cerr << "verification driver failed: " << error.what() << "\n";
      result = kExitCannotRun;
    }
  }
  MPI_Finalize();
  return result;
}

}  // namespace argine::verification
