#pragma once
/// @file CompensatedSum.hpp
/// Reproducible node sums (deck `Parallel: {Reproducible Sums: true}`, doc/parallel.md).
///
/// A P2G sum of n point contributions depends on the order it is added in: one rank adds
/// them in the points' memory order, two ranks add two partial sums at a shared node. The
/// difference is round-off, but local damping (-alpha |f| sign v) turns round-off at a
/// node where v ~ 0 into a force of order alpha |f|, so damped stages drift apart.
///
/// Compensated summation keeps each sum as hi + lo: hi the running double sum, lo the exact
/// rounding error of every addition (Knuth's TwoSum) summed in double. hi + lo is within
/// ~n u^2 sum|x| of the exact sum (u = 2^-53), so fl(hi + lo) is the exact sum correctly
/// rounded, whatever the order and however the ranks split it, unless the exact sum lies
/// that close to a rounding boundary: a chance of order n u sum|x| / |sum x| per value.
///
/// The kernels add through addToNode<kCompensated>: the plain ScatterView access, or the
/// compensated (hi, lo) pair (Kokkos Serial: each sum is added sequentially). A complete sum
/// (after the nodal exchange, NodalExchange::sumCompensated) is folded to hi = fl(hi + lo).

#include "argine/core/Types.hpp"

namespace argine {

class ActiveNodes;

/// hi + lo += v, exactly in the pair: hi = fl(hi + v), lo += the rounding error of that
/// addition (TwoSum: 6 operations, no branch, exact for any magnitudes).
KOKKOS_INLINE_FUNCTION void addCompensated(Real& hi, Real& lo, Real v) {
  const Real sum = hi + v;
  const Real v_part = sum - hi;
  const Real error = (hi - (sum - v_part)) + (v - v_part);
  hi = sum;
  lo += error;
}

/// A compensated running sum as a value (a point total: kinetic energy, liquid mass).
struct CompensatedReal {
  Real hi = 0;
  Real lo = 0;
  KOKKOS_INLINE_FUNCTION void add(Real v) { addCompensated(hi, lo, v); }
  /// Another compensated sum: its hi by TwoSum, its lo as it is (the nodal exchange's rule).
  KOKKOS_INLINE_FUNCTION void add(const CompensatedReal& other) {
    addCompensated(hi, lo, other.hi);
    lo += other.lo;
  }
  /// The sum rounded once.
  KOKKOS_INLINE_FUNCTION Real value() const { return hi + lo; }
};

/// Node i of a scalar nodal sum += v: through the ScatterView access, or compensated into
/// (hi(i), lo(i)).
template <bool kCompensated, class Access, class Hi, class Lo>
KOKKOS_FORCEINLINE_FUNCTION void addToNode(Access& access, const Hi& hi, const Lo& lo, int i,
                                           Real v) {
  if constexpr (kCompensated)
    addCompensated(hi(i), lo(i), v);
  else
    access(i) += v;
}

/// The same for component d of a vector nodal sum.
template <bool kCompensated, class Access, class Hi, class Lo>
KOKKOS_FORCEINLINE_FUNCTION void addToNode(Access& access, const Hi& hi, const Lo& lo, int i, int d,
                                           Real v) {
  if constexpr (kCompensated)
    addCompensated(hi(i, d), lo(i, d), v);
  else
    access(i, d) += v;
}

/// Sums of this rank's points, compensated (reproducible sums: the run totals). Kinetic
/// energies 1/2 M_S |v_S|^2 and, at liquid-carrying points (liquid(material) != 0),
/// 1/2 M_L |v_L|^2, over the located points (element >= 0), with the same terms as the
/// velocity update's own sums.
struct CompensatedKinetic {
  CompensatedReal solid, liquid;
};
CompensatedKinetic compensatedKineticEnergies(
    Kokkos::View<const int*, MemSpace> element_p, Kokkos::View<const int*, MemSpace> material_p,
    Kokkos::View<const int*, MemSpace> liquid_m, Kokkos::View<const Real*, MemSpace> mass_solid_p,
    Kokkos::View<const Real*, MemSpace> mass_liquid_p,
    Kokkos::View<const Real* [kDim], MemSpace> v_solid_p,
    Kokkos::View<const Real* [kDim], MemSpace> v_liquid_p);
/// sum over all points of `values` (e.g. M_L), compensated.
CompensatedReal compensatedSum(Kokkos::View<const Real*, MemSpace> values);

/// hi = fl(hi + lo), lo = 0 at the listed nodes: the compensated sums, complete, rounded once.
/// Folding after every compensated P2G keeps lo zero everywhere for the next one (lo starts
/// zero, and a P2G touches active nodes only).
void foldCompensatedSums(const ActiveNodes& nodes, Kokkos::View<Real*, MemSpace> hi,
                         Kokkos::View<Real*, MemSpace> lo);
void foldCompensatedSums(const ActiveNodes& nodes, Kokkos::View<Real* [kDim], MemSpace> hi,
                         Kokkos::View<Real* [kDim], MemSpace> lo);
void foldCompensatedSums(const ActiveNodes& nodes, Kokkos::View<Real**, MemSpace> hi,
                         Kokkos::View<Real**, MemSpace> lo);

}  // namespace argine
