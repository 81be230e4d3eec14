#include "argine/transfer/CompensatedSum.hpp"

#include "argine/transfer/ActiveNodes.hpp"

namespace argine {

void foldCompensatedSums(const ActiveNodes& active, Kokkos::View<Real*, MemSpace> hi,
                         Kokkos::View<Real*, MemSpace> lo) {
  const auto nodes = active.nodes();
  Kokkos::parallel_for(
      "fold_compensated_sums", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        hi(i) += lo(i);
        lo(i) = 0;
      });
}

void foldCompensatedSums(const ActiveNodes& active, Kokkos::View<Real* [kDim], MemSpace> hi,
                         Kokkos::View<Real* [kDim], MemSpace> lo) {
  const auto nodes = active.nodes();
  Kokkos::parallel_for(
      "fold_compensated_sums", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        for (int d = 0; d < kDim; ++d) {
          hi(i, d) += lo(i, d);
          lo(i, d) = 0;
        }
      });
}

void zeroCompensation(const ActiveNodes& active, Kokkos::View<Real*, MemSpace> lo) {
  const auto nodes = active.nodes();
  Kokkos::parallel_for(
      "zero_compensation", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) { lo(nodes(j)) = 0; });
}

void zeroCompensation(const ActiveNodes& active, Kokkos::View<Real* [kDim], MemSpace> lo) {
  const auto nodes = active.nodes();
  Kokkos::parallel_for(
      "zero_compensation", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        for (int d = 0; d < kDim; ++d) lo(nodes(j), d) = 0;
      });
}

}  // namespace argine
