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
/// x^e for the exponents the soil curves meet most often taken without the library's pow (a
/// call of ~20 ns, a quarter of the implicit seepage step): van Genuchten-Mualem with lambda
/// 0.5 has m = 2 and the powers 0.5, -0.5, 2 and -2. x * x and sqrt are correctly rounded
/// (glibc's pow is too, in nearly all cases); 1/sqrt and 1/(x * x) round twice, within 1 ulp
/// of pow. -0 is taken as +0 (pow's sign rules for an even power), any other e goes to pow.
KOKKOS_INLINE_FUNCTION Real powKnown(Real x, Real e) {
  if (e == 2) return x * x;
  if (e == 0.5) return sqrt(x + 0.0);  // + 0.0: -0 -> +0 as pow(-0, 0.5)
  if (e == -0.5) return 1 / sqrt(x + 0.0);
  if (e == -2) return 1 / (x * x);
  if (e == 1) return x;
  return pow(x, e);
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
KOKKOS_INLINE_FUNCTION Real tan(Real x) {
  return Kokkos::Experimental::tan(x);
}
KOKKOS_INLINE_FUNCTION Real atan(Real x) {
  return Kokkos::Experimental::atan(x);
}
/// sqrt and |x| of each of kLanes points (Lanes.hpp): the IEEE square root, as above. Written per
/// lane: the compiler turns each loop into one vector instruction where errno is off (the library
/// rooms, cmake/ArgineRooms.cmake).
KOKKOS_INLINE_FUNCTION Lanes sqrt(Lanes x) {
  Lanes out;
  for (int l = 0; l < kLanes; ++l) out[l] = __builtin_sqrt(x[l]);
  return out;
}
/// ln x within 1 ulp, with one formula for Real and Lanes: for x in [sqrt(2)/2, sqrt(2)] the
/// k = 0 case of fdlibm's e_log.c (Sun Microsystems 1993, "freely granted"): with f = x - 1,
/// s = f / (2 + f), ln x = f - (f^2/2 - s (f^2/2 + R(s^2))), R the Remez polynomial Lg1..Lg7
/// (error below 2^-58.45 on that interval); elsewhere the library's log. kLanes values in
/// the interval take no call at all, where the library's log is a call per value (with the
/// vector registers saved around each); each lane gets the bits of the one-value form. For
/// the saturated liquid pressure K_L ln(rho_L / rho_L0), whose ratio stays within a few per
/// cent of 1.
template <class T>
KOKKOS_INLINE_FUNCTION T logNearOne(T x) {
  constexpr Real kLg1 = 6.666666666666735130e-01;  // 3FE55555 55555593
  constexpr Real kLg2 = 3.999999999940941908e-01;  // 3FD99999 9997FA04
  constexpr Real kLg3 = 2.857142874366239149e-01;  // 3FD24924 94229359
  constexpr Real kLg4 = 2.222219843214978396e-01;  // 3FCC71C5 1D8E78AF
  constexpr Real kLg5 = 1.818357216161805012e-01;  // 3FC74664 96CB03DE
  constexpr Real kLg6 = 1.531383769920937332e-01;  // 3FC39A09 D078C69F
  constexpr Real kLg7 = 1.479819860511658591e-01;  // 3FC2F112 DF3E5244
  constexpr Real kLow = 0.70710678118654752440, kHigh = 1.41421356237309504880;
  const T f = x - 1;
  const T s = f / (2 + f);
  const T z = s * s, w = z * z;
  const T t1 = w * (kLg2 + w * (kLg4 + w * kLg6));
  const T t2 = z * (kLg1 + w * (kLg3 + w * (kLg5 + w * kLg7)));
  const T half_square = Real(0.5) * f * f;
  const T near = f - (half_square - s * (half_square + (t2 + t1)));
  const auto inside = both(x >= kLow, x <= kHigh);
  if constexpr (std::is_same_v<T, Real>) {
    return inside ? near : log(x);
  } else {
    if (!anyLane(~inside)) return near;
    T out;
    for (int l = 0; l < kLanes; ++l) out[l] = inside[l] ? near[l] : log(x[l]);
    return out;
  }
}

/// e^x within 1 ulp, with one formula for Real and Lanes: for |x| <= 2^-8 the Taylor
/// polynomial 1 + x + x^2/2 + ... + x^5/5! (the remainder x^6/6! e^|x| is below 2^-57 there,
/// a thirtieth of an ulp of the result; the sum past the leading 1 is taken in Horner form
/// and added last); elsewhere the library's exp. For the liquid density rho_L0 e^(p_L/K_L)
/// (4.13), whose exponent stays below 1e-3 for any pressure a soil sees (K_L = 2.2 GPa): a
/// call of ~12 ns per value, twice per unsaturated point and step, became five multiplies
/// and five adds (P11 item 4).
template <class T>
KOKKOS_INLINE_FUNCTION T expNearZero(T x) {
  constexpr Real kBound = 0.00390625;  // 2^-8
  const T tail =
      x * (1 + x * (Real(1) / 2 + x * (Real(1) / 6 + x * (Real(1) / 24 + x * (Real(1) / 120)))));
  const T near = 1 + tail;
  const auto inside = both(x >= -kBound, x <= kBound);
  if constexpr (std::is_same_v<T, Real>) {
    return inside ? near : exp(x);
  } else {
    if (!anyLane(~inside)) return near;
    T out;
    for (int l = 0; l < kLanes; ++l) out[l] = inside[l] ? near[l] : exp(x[l]);
    return out;
  }
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
/// fmax of each lane, the bits of the Real form.
KOKKOS_INLINE_FUNCTION Lanes fmax(Lanes x, Lanes y) {
  return select(x != x, y, select(y > x, y, x));
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
