#pragma once
/// @file Lanes.hpp
/// Several material points in one instruction (SIMD across points): `Lanes` holds one value
/// of kLanes consecutive points, and the per-point formulas that are templates on their value
/// type (Real or Lanes) run on all of them at once. Every operation on Lanes is the IEEE
/// operation of each lane (+, -, *, /, sqrt, fabs, comparisons; -ffp-contract=off keeps a * b
/// + c two roundings here too), so a lane gets the same bits as the scalar formula gives its
/// point. Branches are written as select(), which for Real is the plain conditional.
///
/// A GCC/Clang vector extension, not a library type: the compiler emits the vector
/// instructions of the target (AVX2/AVX-512: one register; SSE2: two), and the same source
/// compiles on any of them.

#include <cstring>
#include <type_traits>

#include "argine/core/Types.hpp"

#if defined(__AVX__)
#include <immintrin.h>
#endif

namespace argine {

/// Points per Lanes value: 4 doubles, one AVX register.
inline constexpr int kLanes = 4;

/// One Real of kLanes points.
typedef Real Lanes __attribute__((vector_size(kLanes * sizeof(Real))));

/// The result of comparing two Lanes: all bits set in a lane where the comparison holds.
using LaneMask = decltype(Lanes{} < Lanes{});

/// The value type's counterpart of a constant: x itself for Real, x in every lane for Lanes.
template <class T>
KOKKOS_INLINE_FUNCTION T splat(Real x) {
  if constexpr (std::is_same_v<T, Real>)
    return x;
  else
    return T{} + x;
}

/// `condition ? a : b`, per lane for Lanes.
KOKKOS_INLINE_FUNCTION Real select(bool condition, Real a, Real b) {
  return condition ? a : b;
}
KOKKOS_INLINE_FUNCTION Lanes select(LaneMask condition, Lanes a, Lanes b) {
  LaneMask bits_a, bits_b;
  std::memcpy(&bits_a, &a, sizeof a);
  std::memcpy(&bits_b, &b, sizeof b);
  const LaneMask bits = (condition & bits_a) | (~condition & bits_b);
  Lanes out;
  std::memcpy(&out, &bits, sizeof out);
  return out;
}

/// a and b, a or b: of two conditions, or per lane of two LaneMasks.
KOKKOS_INLINE_FUNCTION bool both(bool a, bool b) {
  return a && b;
}
KOKKOS_INLINE_FUNCTION LaneMask both(LaneMask a, LaneMask b) {
  return a & b;
}
KOKKOS_INLINE_FUNCTION bool either(bool a, bool b) {
  return a || b;
}
KOKKOS_INLINE_FUNCTION LaneMask either(LaneMask a, LaneMask b) {
  return a | b;
}

/// Whether the condition holds in any lane (for Real: the condition).
KOKKOS_INLINE_FUNCTION bool anyLane(bool condition) {
  return condition;
}
/// With AVX one test of the whole register (vptest): the fold below compiled to four moves
/// out of the register and three ors, 6.5 % of the point-state pass of the levee (perf).
KOKKOS_INLINE_FUNCTION bool anyLane(LaneMask condition) {
#if defined(__AVX__)
  static_assert(sizeof(LaneMask) == sizeof(__m256i));
  __m256i bits;
  std::memcpy(&bits, &condition, sizeof bits);
  return !_mm256_testz_si256(bits, bits);
#else
  LaneMask folded = condition;
  for (int l = 1; l < kLanes; ++l) folded[0] |= condition[l];
  return folded[0] != 0;
#endif
}

/// out[l] = (in[0][l], in[1][l], in[2][l], in[3][l]): four values of kLanes points turned into
/// the four values of each point (a 4 x 4 transpose, eight shuffles).
KOKKOS_FORCEINLINE_FUNCTION void transposeLanes(const Lanes in[kLanes], Lanes out[kLanes]) {
  const Lanes low01 = __builtin_shufflevector(in[0], in[1], 0, 4, 2, 6);
  const Lanes high01 = __builtin_shufflevector(in[0], in[1], 1, 5, 3, 7);
  const Lanes low23 = __builtin_shufflevector(in[2], in[3], 0, 4, 2, 6);
  const Lanes high23 = __builtin_shufflevector(in[2], in[3], 1, 5, 3, 7);
  out[0] = __builtin_shufflevector(low01, low23, 0, 1, 4, 5);
  out[1] = __builtin_shufflevector(high01, high23, 0, 1, 4, 5);
  out[2] = __builtin_shufflevector(low01, low23, 2, 3, 6, 7);
  out[3] = __builtin_shufflevector(high01, high23, 2, 3, 6, 7);
}

/// The value of `view` at point p (Real), or at points p .. p + kLanes - 1 (Lanes).
template <class T, class View>
KOKKOS_INLINE_FUNCTION T load(const View& view, int p) {
  if constexpr (std::is_same_v<T, Real>) {
    return view(p);
  } else {
    static_assert(!std::is_same_v<typename View::array_layout, Kokkos::LayoutStride>,
                  "load<Lanes> reads kLanes consecutive values");
    T out;
    std::memcpy(&out, &view(p), sizeof out);
    return out;
  }
}

/// Component c of a (point, component) View at point p, or at points p .. p + kLanes - 1.
template <class T, class View>
KOKKOS_INLINE_FUNCTION T load(const View& view, int p, int c) {
  if constexpr (std::is_same_v<T, Real>) {
    return view(p, c);
  } else if constexpr (std::is_same_v<typename View::array_layout, Kokkos::LayoutRight> &&
                       View::static_extent(1) == 2 && kLanes == 4) {
    // (x, y) pairs: the kLanes points' 8 values are contiguous, two vector loads and a
    // shuffle, where the lane-by-lane inserts cost more and may go through the stack (a
    // store-forwarding stall when the vector is read back).
    Lanes low, high;
    std::memcpy(&low, &view(p, 0), sizeof low);
    std::memcpy(&high, &view(p + 2, 0), sizeof high);
    return c == 0 ? __builtin_shufflevector(low, high, 0, 2, 4, 6)
                  : __builtin_shufflevector(low, high, 1, 3, 5, 7);
  } else {
    T out;
    for (int l = 0; l < kLanes; ++l) out[l] = view(p + l, c);
    return out;
  }
}

/// Writes what load() reads.
template <class View>
KOKKOS_INLINE_FUNCTION void store(const View& view, int p, Real value) {
  view(p) = value;
}
template <class View>
KOKKOS_INLINE_FUNCTION void store(const View& view, int p, Lanes value) {
  std::memcpy(&view(p), &value, sizeof value);
}
template <class View>
KOKKOS_INLINE_FUNCTION void store(const View& view, int p, int c, Real value) {
  view(p, c) = value;
}
template <class View>
KOKKOS_INLINE_FUNCTION void store(const View& view, int p, int c, Lanes value) {
  for (int l = 0; l < kLanes; ++l) view(p + l, c) = value[l];
}

/// All components of a (point, component) View at point p (Real), or at points p .. p +
/// kLanes - 1 (Lanes): out[c] = load<T>(view, p, c) for every c. Where the kLanes points'
/// values are contiguous (LayoutRight, 2 or 4 components), a few vector loads and shuffles
/// instead of a scalar load and an insert per value.
template <class T, class View>
KOKKOS_FORCEINLINE_FUNCTION void loadComponents(const View& view, int p, T out[]) {
  constexpr int kComponents = static_cast<int>(View::static_extent(1));
  if constexpr (std::is_same_v<T, Lanes> &&
                std::is_same_v<typename View::array_layout, Kokkos::LayoutRight> &&
                kComponents == kLanes) {
    Lanes rows[kLanes];  // rows[l] = the components of point p + l
    std::memcpy(rows, &view(p, 0), sizeof rows);
    transposeLanes(rows, out);
  } else {
    for (int c = 0; c < kComponents; ++c) out[c] = load<T>(view, p, c);
  }
}

/// Writes what loadComponents() reads.
template <class T, class View>
KOKKOS_FORCEINLINE_FUNCTION void storeComponents(const View& view, int p, const T in[]) {
  constexpr int kComponents = static_cast<int>(View::static_extent(1));
  if constexpr (std::is_same_v<T, Lanes> &&
                std::is_same_v<typename View::array_layout, Kokkos::LayoutRight> &&
                kComponents == kLanes) {
    Lanes rows[kLanes];
    transposeLanes(in, rows);
    std::memcpy(&view(p, 0), rows, sizeof rows);
  } else if constexpr (std::is_same_v<T, Lanes> &&
                       std::is_same_v<typename View::array_layout, Kokkos::LayoutRight> &&
                       kComponents == 2 && kLanes == 4) {
    // (x, y) pairs of the four points: two shuffles, two vector stores.
    const Lanes low = __builtin_shufflevector(in[0], in[1], 0, 4, 1, 5);
    const Lanes high = __builtin_shufflevector(in[0], in[1], 2, 6, 3, 7);
    std::memcpy(&view(p, 0), &low, sizeof low);
    std::memcpy(&view(p + 2, 0), &high, sizeof high);
  } else {
    for (int c = 0; c < kComponents; ++c) store(view, p, c, in[c]);
  }
}

}  // namespace argine
