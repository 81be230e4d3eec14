#include "argine/transfer/CompensatedSum.hpp"

#include "argine/transfer/ActiveNodes.hpp"

namespace argine {

namespace {

/// hi = the folded sum of the parts (hi, lo) of entry (i, c), lo = 0.
template <class Hi, class Lo, class... Index>
KOKKOS_INLINE_FUNCTION void foldAt(const Hi& hi, const Lo& lo, Index... index) {
  Real parts[kSumParts];
  parts[0] = hi(index...);
  for (int k = 0; k < kLowParts; ++k) {
    parts[k + 1] = lo[k](index...);
    lo[k](index...) = 0;
  }
  hi(index...) = foldSum(parts);
}

}  // namespace

void foldCompensatedSums(const ActiveNodes& active, Kokkos::View<Real*, MemSpace> hi,
                         const LowParts<Kokkos::View<Real*, MemSpace>>& lo) {
  const auto nodes = active.nodes();
  Kokkos::parallel_for(
      "fold_compensated_sums", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) { foldAt(hi, lo, nodes(j)); });
}

void foldCompensatedSums(const ActiveNodes& active, Kokkos::View<Real* [kDim], MemSpace> hi,
                         const LowParts<Kokkos::View<Real* [kDim], MemSpace>>& lo) {
  const auto nodes = active.nodes();
  Kokkos::parallel_for(
      "fold_compensated_sums", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        for (int d = 0; d < kDim; ++d) foldAt(hi, lo, nodes(j), d);
      });
}

void foldCompensatedSums(const ActiveNodes& active, Kokkos::View<Real**, MemSpace> hi,
                         const LowParts<Kokkos::View<Real**, MemSpace>>& lo) {
  const auto nodes = active.nodes();
  const int columns = static_cast<int>(hi.extent(1));
  Kokkos::parallel_for(
      "fold_compensated_sums", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        for (int k = 0; k < columns; ++k) foldAt(hi, lo, nodes(j), k);
      });
}

void foldCompensatedSums(Kokkos::View<Real**, MemSpace> hi,
                         const LowParts<Kokkos::View<Real**, MemSpace>>& lo) {
  const int columns = static_cast<int>(hi.extent(1));
  Kokkos::parallel_for(
      "fold_compensated_rows", Kokkos::RangePolicy<ExecSpace>(0, hi.extent(0)),
      KOKKOS_LAMBDA(const int e) {
        for (int k = 0; k < columns; ++k) foldAt(hi, lo, e, k);
      });
}

CompensatedKinetic compensatedKineticEnergies(
    Kokkos::View<const int*, MemSpace> element_p, Kokkos::View<const int*, MemSpace> material_p,
    Kokkos::View<const int*, MemSpace> liquid_m, Kokkos::View<const Real*, MemSpace> mass_solid_p,
    Kokkos::View<const Real*, MemSpace> mass_liquid_p,
    Kokkos::View<const Real* [kDim], MemSpace> v_solid_p,
    Kokkos::View<const Real* [kDim], MemSpace> v_liquid_p) {
  // Sequential on the host (Serial): a compensated sum is added in one order.
  static_assert(Kokkos::SpaceAccessibility<Kokkos::HostSpace, MemSpace>::accessible,
                "compensated totals are summed on the host");
  CompensatedKinetic totals;
  const int count = static_cast<int>(element_p.extent(0));
  for (int p = 0; p < count; ++p) {
    if (element_p(p) < 0) continue;
    const Real vsx = v_solid_p(p, 0), vsy = v_solid_p(p, 1);
    totals.solid.add(0.5 * mass_solid_p(p) * (vsx * vsx + vsy * vsy));
    if (liquid_m(material_p(p)) == 0) continue;
    const Real vlx = v_liquid_p(p, 0), vly = v_liquid_p(p, 1);
    totals.liquid.add(0.5 * mass_liquid_p(p) * (vlx * vlx + vly * vly));
  }
  return totals;
}

CompensatedReal compensatedSum(Kokkos::View<const Real*, MemSpace> values) {
  static_assert(Kokkos::SpaceAccessibility<Kokkos::HostSpace, MemSpace>::accessible,
                "compensated totals are summed on the host");
  CompensatedReal sum;
  for (std::size_t p = 0; p < values.extent(0); ++p) sum.add(values(p));
  return sum;
}

}  // namespace argine
