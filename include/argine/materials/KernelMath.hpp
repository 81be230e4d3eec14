#pragma once
/// @file KernelMath.hpp
/// The few math functions the material and time-step kernels use, wrapped once so that
/// KOKKOS_INLINE_FUNCTION code calls Kokkos' portable versions (Kokkos 3.4 keeps them in
/// Kokkos::Experimental; later versions move them to Kokkos::).

#include <Kokkos_MathematicalFunctions.hpp>
#include <Kokkos_NumericTraits.hpp>

#include "argine/core/Lanes.hpp"
#include "argine/core/Types.hpp"

namespace argine::kmath {

KOKKOS_INLINE_FUNCTION Real sqrt(Real x) {
  return Kokkos::Experimental::sqrt(x);
}
KOKKOS_INLINE_FUNCTION Real exp(Real x) {
  return Kokkos::Experimental::exp(x);
}
KOKKOS_INLINE_FUNCTION Real log(Real x) {
  return Kokkos::Experimental::log(x);
}
KOKKOS_INLINE_FUNCTION Real pow(Real x, Real y) {
  return Kokkos::Experimental::pow(x, y);
}
KOKKOS_INLINE_FUNCTION Real sin(Real x) {
  return Kokkos::Experimental::sin(x);
}
KOKKOS_INLINE_FUNCTION Real cos(Real x) {
  return Kokkos::Experimental::cos(x);
}
KOKKOS_INLINE_FUNCTION Real fabs(Real x) {
  return Kokkos::Experimental::fabs(x);
}
/// sqrt and |x| of each of kLanes points (Lanes.hpp): the IEEE square root, as above. Written per
/// lane: the compiler turns each loop into one vector instruction where errno is off (the library
/// rooms, cmake/ArgineRooms.cmake).
KOKKOS_INLINE_FUNCTION Lanes sqrt(Lanes x) {
  Lanes out;
  for (int l = 0; l < kLanes; ++l) out[l] = __builtin_sqrt(x[l]);
  return out;
}
/// The library logarithm of each lane, one call per lane (so the same bits as the scalar one).
KOKKOS_INLINE_FUNCTION Lanes log(Lanes x) {
  Lanes out;
  for (int l = 0; l < kLanes; ++l) out[l] = Kokkos::Experimental::log(x[l]);
  return out;
}
KOKKOS_INLINE_FUNCTION Lanes fabs(Lanes x) {
  Lanes out;
  for (int l = 0; l < kLanes; ++l) out[l] = __builtin_fabs(x[l]);
  return out;
}

// fmin and fmax as C99 defines them (a NaN argument gives the other one), written out: the
// library's fmin/fmax is a call on x86-64 without AVX-512 (a hot one in the time-step
// criteria), while these compile to minsd/maxsd and a blend. The same values, except that
// the sign of a zero result may differ, which C99 leaves open too.
KOKKOS_INLINE_FUNCTION Real fmin(Real x, Real y) {
  if (x != x) return y;
  return y < x ? y : x;
}
KOKKOS_INLINE_FUNCTION Real fmax(Real x, Real y) {
  if (x != x) return y;
  return y > x ? y : x;
}

/// Whether x is finite (neither infinite nor NaN), per lane for Lanes.
KOKKOS_INLINE_FUNCTION bool isFinite(Real x) {
  return Kokkos::Experimental::isfinite(x);
}
KOKKOS_INLINE_FUNCTION LaneMask isFinite(Lanes x) {
  return fabs(x) <= Kokkos::Experimental::finite_max<Real>::value;
}

/// +infinity: the "no limit" value of a time-step criterion that does not apply.
KOKKOS_INLINE_FUNCTION constexpr Real infinity() {
  return Kokkos::Experimental::infinity<Real>::value;
}

/// A quiet NaN: poisons a result that must never be used (caught by the run's
/// non-finite check).
KOKKOS_INLINE_FUNCTION Real quietNaN() {
  return Kokkos::Experimental::nan("");
}

}  // namespace argine::kmath
