#pragma once
/// @file CompensatedSum.hpp
/// Reproducible node sums (deck `Parallel: {Reproducible Sums: true}`, doc/parallel.md).
///
/// A P2G sum of n point contributions depends on the order it is added in: one rank adds
/// them in the points' memory order, two ranks add two partial sums at a shared node. The
/// difference is round-off, but local damping (-alpha |f| sign v) turns round-off at a
/// node where v ~ 0 into a force of order alpha |f|, so damped stages drift apart.
///
/// Binned sums (the pre-rounding of Demmel and Nguyen's reproducible summation, ReproBLAS):
/// the exponent range is cut into bins of kSumBinBits bits at fixed places (bin b holds the
/// bits of weight 2^(b W - kSumBinBias) .. 2^((b + 1) W - kSumBinBias - 1)). A sum keeps the
/// kSumBins bins from the bin of its largest term down: each term is cut at the bins'
/// boundaries (by clearing mantissa bits, exact) and each piece is added to its bin, where
/// it is a multiple of the bin's quantum below 2^W quanta, so that the bin's sum of up to
/// 2^(53 - W) pieces is exact. What a term has below the lowest bin is dropped. When a larger
/// term raises the top bin, the bins move down and the lowest are dropped: they hold the
/// pieces that the new lowest boundary cuts off every term, added so far or later. So the
/// bins, and the value they hold, depend only on the terms, not on their order nor on how
/// they are split into partial sums (ranks): merging two sums (their bins aligned, added)
/// is exact too. The value is the exact sum of the terms cut at 2^-112 to 2^-139 of the
/// largest, and the folded sum is that value correctly rounded: the exact sum correctly
/// rounded unless it lies within n 2^-112 |largest term| of a rounding boundary, and the
/// same double in every order either way.
///
/// (Until P9 a sum was kept as a TwoSum pair hi + lo, lo summed in double: its rounding
/// depended on the order when the exact sum lay within ~n u^2 sum|x| of a rounding boundary.
/// It happened: a force at a node of the GIMP + APIC Mohr-Coulomb block, 6.42e-8 N from
/// terms of up to 144 N, lay 5e-30 N from a midpoint, and 2 ranks rounded it the other way.)
///
/// Storage: part 0 of a sum is the caller's own field (bin 0; the folded sum after the
/// fold), parts 1..kLowParts the low parts (bins 1..kSumBins - 1 and the top bin's number
/// + 1, 0 for an empty sum), all zero before the first term. A non-finite term makes the sum
/// the plain sum of its non-finite terms (part 0; tag -1). The kernels add through
/// addToNode<kCompensated>: the plain ScatterView access, or the binned parts (Kokkos
/// Serial: each sum is added sequentially). A complete sum (after the nodal exchange,
/// NodalExchange::sumCompensated) is folded: part 0 = the sum, the low parts zero.

#include <cstdint>
#include <cstring>
#include <string>

#include "argine/core/Types.hpp"

namespace argine {

class ActiveNodes;

inline constexpr int kSumBins = 5;      ///< bins kept per sum
inline constexpr int kSumBinBits = 28;  ///< bits per bin (W): a bin is exact up to 2^25 terms
inline constexpr int kSumBinBias = 1022;
inline constexpr int kSumParts = kSumBins + 1;   ///< the bins and the top bin's number
inline constexpr int kLowParts = kSumParts - 1;  ///< parts besides the caller's field

/// One object of type T per low part (the low parts of GridFields, of a View, ...).
template <class T>
using LowParts = Kokkos::Array<T, kLowParts>;

namespace binned {

KOKKOS_FORCEINLINE_FUNCTION std::uint64_t bitsOf(Real x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

KOKKOS_FORCEINLINE_FUNCTION Real realOf(std::uint64_t b) {
  Real x;
  std::memcpy(&x, &b, sizeof x);
  return x;
}

/// 2^k, k in the range of normal doubles.
KOKKOS_FORCEINLINE_FUNCTION Real powerOfTwo(int k) {
  return realOf(static_cast<std::uint64_t>(k + 1023) << 52);
}

/// x 2^k, exact where the result is a double (k may take x through the subnormal range).
KOKKOS_INLINE_FUNCTION Real scaled(Real x, int k) {
  while (k > 1000) x *= powerOfTwo(1000), k -= 1000;
  while (k < -1000) x *= powerOfTwo(-1000), k += 1000;
  return x * powerOfTwo(k);
}

/// The quantum exponent of bin number b: its pieces are multiples of 2^quantumOf(b).
KOKKOS_FORCEINLINE_FUNCTION int quantumOf(int b) {
  return b * kSumBinBits - kSumBinBias;
}

/// The top bin's number of a sum's parts from part kSumBins, the tag: number + 1 (>= 1),
/// 0 for an empty sum (-1), -1 for a sum with a non-finite term (-2).
KOKKOS_FORCEINLINE_FUNCTION int topOf(Real tag) {
  return static_cast<int>(tag) - 1;
}
inline constexpr Real kSpecialTag = -1;

/// Moves the bins of a sum down by `shift` (its top bin raised by as many), dropping the
/// lowest.
template <class Part>
KOKKOS_INLINE_FUNCTION void moveDown(const Part& part, int shift) {
  for (int k = kSumBins - 1; k >= 0; --k) part(k) = k >= shift ? part(k - shift) : Real(0);
}

/// addToSum's rare cases: an empty sum, a term of a higher bin than the top (the bins move
/// down), a non-finite term or sum (the sum becomes the plain sum of its non-finite terms).
/// Returns the top bin, or -1 when v is done with.
template <class Part>
KOKKOS_INLINE_FUNCTION int raiseTop(const Part& part, int top, int bin, int exponent, Real v) {
  Real& tag = part(kSumBins);
  if (exponent == 0x7ff || tag == kSpecialTag) {
    if (tag != kSpecialTag) {
      for (int k = 0; k < kSumBins; ++k) part(k) = 0;
      tag = kSpecialTag;
    }
    if (exponent == 0x7ff) part(0) += v;  // (finite terms no longer count)
    return -1;
  }
  if (top >= 0) moveDown(part, bin - top);
  tag = bin + 1;
  return bin;
}

}  // namespace binned

/// The sum whose parts are part(0) .. part(kSumParts - 1) (Real&) += v. Exact bin by bin:
/// the order of the terms does not change the parts.
template <class Part>
KOKKOS_FORCEINLINE_FUNCTION void addToSumParts(const Part& part, Real v) {
  using namespace binned;
  static_assert(kSumBinBias == 1022 && 2 * kSumBinBits >= 53,
                "a term's bits lie in its own bin and the next two");
  if (v == 0) return;  // +0 and -0 add nothing (an empty sum folds to +0, as 0 + -0 does)
  const std::uint64_t bits = bitsOf(v);
  const int exponent = static_cast<int>((bits >> 52) & 0x7ff);
  const int e = exponent + (exponent == 0);  // subnormal: the bits of 2^-1074 and up
  const int bin = (e - 1) / kSumBinBits;     // (e - 1023 + kSumBinBias) / W
  int top = topOf(part(kSumBins));
  if (top < bin || exponent == 0x7ff) {
    top = raiseTop(part, top, bin, exponent, v);
    if (top < 0) return;
  }
  // v's bits below the quantum 2^(bin W - bias) of its bin, and below the next bin's: the
  // pieces of the three bins are v cut there, by clearing mantissa bits (exact).
  const int drop = bin * kSumBinBits - e + 53;  // in [53 - W, 52]
  const int next_drop = drop - kSumBinBits;
  const std::uint64_t top_mask = ~((std::uint64_t(1) << drop) - 1);
  const std::uint64_t next_mask =
      next_drop > 0 ? ~((std::uint64_t(1) << next_drop) - 1) : ~std::uint64_t(0);
  const Real cut = realOf(bits & top_mask), next_cut = realOf(bits & next_mask);
  const int k = top - bin;
  if (k < kSumBins) part(k) += cut;
  if (k + 1 < kSumBins) part(k + 1) += next_cut - cut;
  if (k + 2 < kSumBins) part(k + 2) += v - next_cut;  // (+0 where next_drop <= 0)
}

/// The same for parts given as kSumParts pointers.
template <class Parts>
KOKKOS_FORCEINLINE_FUNCTION void addToSum(const Parts& p, Real v) {
  addToSumParts([&](int k) -> Real& { return *p[k]; }, v);
}

/// The sum in parts `into` (pointers) += the sum in parts `from` (values): the bins aligned
/// on the higher top and added, exactly; the same parts as adding from's terms one by one.
template <class Parts>
KOKKOS_INLINE_FUNCTION void addSumToSum(const Parts& into, const Real (&from)[kSumParts]) {
  using namespace binned;
  const auto part = [&](int k) -> Real& { return *into[k]; };
  const Real from_tag = from[kSumBins];
  Real& tag = part(kSumBins);
  if (from_tag == 0 || (tag == kSpecialTag && from_tag != kSpecialTag)) return;
  if (from_tag == kSpecialTag || tag == 0) {
    if (tag == kSpecialTag)
      part(0) += from[0];
    else
      for (int k = 0; k < kSumParts; ++k) part(k) = from[k];
    return;
  }
  int top = topOf(tag);
  const int from_top = topOf(from_tag);
  if (top < from_top) {
    moveDown(part, from_top - top);
    top = from_top;
    tag = from_tag;
  }
  const int shift = top - from_top;
  for (int k = shift; k < kSumBins; ++k) part(k) += from[k - shift];
}

namespace binned {

/// x / 2^q for x a multiple of 2^q below 2^(q + 53) in magnitude (a bin's sum): exact.
KOKKOS_FORCEINLINE_FUNCTION std::int64_t quantaOf(Real x, int q) {
  const std::uint64_t b = bitsOf(x);
  int exponent = static_cast<int>((b >> 52) & 0x7ff);
  std::uint64_t mantissa = b & ((std::uint64_t(1) << 52) - 1);
  if (exponent != 0)
    mantissa |= std::uint64_t(1) << 52;
  else
    exponent = 1;
  const int shift = exponent - 1075 - q;  // x = mantissa 2^(exponent - 1075)
  const std::uint64_t m =
      shift >= 0 ? mantissa << shift : (shift > -64 ? mantissa >> -shift : std::uint64_t(0));
  return (b >> 63) != 0 ? -static_cast<std::int64_t>(m) : static_cast<std::int64_t>(m);
}

/// Bits [n, n + 64) of the 192-bit w (zeros above).
KOKKOS_FORCEINLINE_FUNCTION std::uint64_t bitsFrom(const std::uint64_t (&w)[3], int n) {
  const int j = n / 64, r = n % 64;
  const std::uint64_t low = j < 3 ? w[j] >> r : 0;
  const std::uint64_t high = r != 0 && j + 1 < 3 ? w[j + 1] << (64 - r) : 0;
  return low | high;
}

/// Whether any of bits [0, n) of w is set.
KOKKOS_FORCEINLINE_FUNCTION bool anyBitBelow(const std::uint64_t (&w)[3], int n) {
  const int j = n / 64, r = n % 64;
  for (int i = 0; i < j && i < 3; ++i)
    if (w[i] != 0) return true;
  return j < 3 && r != 0 && (w[j] & ((std::uint64_t(1) << r) - 1)) != 0;
}

/// The finite bins of a sum (top bin `top`) correctly rounded: the bins as one 192-bit
/// integer of quanta of the lowest bin, rounded to nearest (ties to even).
KOKKOS_INLINE_FUNCTION Real foldExactly(const Real (&p)[kSumParts], int top) {
  const int bottom = quantumOf(top - kSumBins + 1);  // quantum of the lowest bin
  // T = sum_k m_k 2^((kSumBins - 1 - k) W), m_k = p[k] / 2^quantum(k), |m_k| < 2^53, in three
  // 64-bit words, two's complement (|T| < 2^(53 + 4 W + 3) = 2^168)
  static_assert((kSumBins - 1) * kSumBinBits + 53 + 3 < 191, "T fits in 192 bits");
  std::uint64_t w[3] = {0, 0, 0};
  for (int k = 0; k < kSumBins; ++k) {
    if (p[k] == 0) continue;
    const std::int64_t m = quantaOf(p[k], quantumOf(top - k));
    const int shift = (kSumBins - 1 - k) * kSumBinBits;
    const std::uint64_t sign = m < 0 ? ~std::uint64_t(0) : 0;
    const std::uint64_t um = static_cast<std::uint64_t>(m);
    std::uint64_t term[3];
    const int r = shift % 64;
    if (shift < 64) {
      term[0] = um << r;
      term[1] = r != 0 ? (um >> (64 - r)) | (sign << r) : sign;
      term[2] = sign;
    } else {
      term[0] = 0;
      term[1] = um << r;
      term[2] = r != 0 ? (um >> (64 - r)) | (sign << r) : sign;
    }
    std::uint64_t carry = 0;
    for (int j = 0; j < 3; ++j) {
      const std::uint64_t s = w[j] + term[j];
      const std::uint64_t c1 = s < w[j] ? 1 : 0;
      w[j] = s + carry;
      carry = c1 | (w[j] < s ? 1 : 0);
    }
  }
  const bool negative = (w[2] >> 63) != 0;
  if (negative) {  // |T|
    std::uint64_t carry = 1;
    for (int j = 0; j < 3; ++j) {
      w[j] = ~w[j] + carry;
      carry = carry != 0 && w[j] == 0 ? 1 : 0;
    }
  }
  int lead = -1;  // highest set bit of |T|
  for (int j = 2; j >= 0 && lead < 0; --j)
    if (w[j] != 0) lead = 64 * j + 63 - __builtin_clzll(w[j]);
  if (lead < 0) return 0;
  // keep 53 bits, or fewer where the result is subnormal (its last bit is 2^-1074)
  int drop = lead - 52;
  if (drop < -1074 - bottom) drop = -1074 - bottom;
  if (drop < 0) drop = 0;  // |T| has 53 bits or fewer: exact
  std::uint64_t mantissa = drop > lead ? 0 : bitsFrom(w, drop);
  if (drop > 0 && drop - 1 <= lead && ((bitsFrom(w, drop - 1) & 1) != 0) &&
      ((mantissa & 1) != 0 || anyBitBelow(w, drop - 1)))
    ++mantissa;  // above the half way, or on it and odd
  const Real magnitude = scaled(static_cast<Real>(mantissa), drop + bottom);
  return negative ? -magnitude : magnitude;
}

}  // namespace binned

/// The value of the sum in parts p, correctly rounded. The bins summed with TwoSum give the
/// sum as s + c, c the rounding errors summed in double: fl(s + c) is the rounded exact sum
/// unless the exact sum may lie on the other side of a rounding boundary (within the error
/// bound of c of it), where foldExactly decides (rarely: ties and near-ties).
KOKKOS_INLINE_FUNCTION Real foldSum(const Real (&p)[kSumParts]) {
  using namespace binned;
  const Real tag = p[kSumBins];
  if (tag == 0) return 0;
  if (tag == kSpecialTag) return p[0];
  Real s = p[0], c = 0, bound = 0;
  for (int k = 1; k < kSumBins; ++k) {
    const Real sum = s + p[k], part = sum - s;
    const Real error = (s - (sum - part)) + (p[k] - part);
    s = sum;
    c += error;
    bound += Kokkos::Experimental::fabs(error);
  }
  if (!(s - s == 0)) {  // a bin overflowed (or the sum does): inf or NaN, as a plain sum gives
    Real plain = 0;
    for (int k = 0; k < kSumBins; ++k) plain += p[k];
    return plain;
  }
  const Real r = s + c, r_part = r - s;
  const Real d = (s - (r - r_part)) + (c - r_part);  // s + c = r + d exactly
  // |c - the exact sum of the errors| <= 4 u sum|error| (3 additions); the distance from r to
  // the next boundary is half its gap, a quarter of its ulp below a power of two
  const std::uint64_t bits = bitsOf(r);
  const int exponent = static_cast<int>((bits >> 52) & 0x7ff);
  if (exponent > 54 && exponent < 0x7ff) {  // r normal, its quarter ulp too
    const Real quarter_ulp = realOf(static_cast<std::uint64_t>(exponent - 54) << 52);
    const Real margin = Kokkos::Experimental::fabs(d) + 0x1p-50 * bound;
    if (margin < quarter_ulp ||
        (margin < 2 * quarter_ulp && (bits & ((std::uint64_t(1) << 52) - 1)) != 0))
      return r;
  }
  return foldExactly(p, topOf(tag));
}

/// The parts of a sum stored in the caller's field `hi` and its low parts `lo` at index i
/// (node or element) and component d (vector fields).
template <class Hi, class Lo>
KOKKOS_FORCEINLINE_FUNCTION void partsAt(const Hi& hi, const Lo& lo, int i, Real* (&p)[kSumParts]) {
  p[0] = &hi(i);
  for (int k = 0; k < kLowParts; ++k) p[k + 1] = &lo[k](i);
}
template <class Hi, class Lo>
KOKKOS_FORCEINLINE_FUNCTION void partsAt(const Hi& hi, const Lo& lo, int i, int d,
                                         Real* (&p)[kSumParts]) {
  p[0] = &hi(i, d);
  for (int k = 0; k < kLowParts; ++k) p[k + 1] = &lo[k](i, d);
}

/// A reproducible sum as a value (a point total: kinetic energy, liquid mass).
struct CompensatedReal {
  Real part[kSumParts] = {};
  KOKKOS_INLINE_FUNCTION void add(Real v) {
    Real* p[kSumParts];
    for (int k = 0; k < kSumParts; ++k) p[k] = &part[k];
    addToSum(p, v);
  }
  /// Another sum's terms (the merge of the nodal exchange).
  KOKKOS_INLINE_FUNCTION void add(const CompensatedReal& other) {
    Real* p[kSumParts];
    for (int k = 0; k < kSumParts; ++k) p[k] = &part[k];
    addSumToSum(p, other.part);
  }
  /// The sum rounded once.
  KOKKOS_INLINE_FUNCTION Real value() const { return foldSum(part); }
};

/// Node i of a scalar nodal sum += v: through the ScatterView access, or into the parts
/// (hi(i), lo[k](i)).
template <bool kCompensated, class Access, class Hi, class Lo>
KOKKOS_FORCEINLINE_FUNCTION void addToNode(Access& access, const Hi& hi, const Lo& lo, int i,
                                           Real v) {
  if constexpr (kCompensated) {
    Real* p[kSumParts];
    partsAt(hi, lo, i, p);
    addToSum(p, v);
  } else {
    access(i) += v;
  }
}

/// The same for component d of a vector nodal sum.
template <bool kCompensated, class Access, class Hi, class Lo>
KOKKOS_FORCEINLINE_FUNCTION void addToNode(Access& access, const Hi& hi, const Lo& lo, int i, int d,
                                           Real v) {
  if constexpr (kCompensated) {
    Real* p[kSumParts];
    partsAt(hi, lo, i, d, p);
    addToSum(p, v);
  } else {
    access(i, d) += v;
  }
}

/// Sums of this rank's points, reproducible (the run totals). Kinetic energies 1/2 M_S |v_S|^2
/// and, at liquid-carrying points (liquid(material) != 0), 1/2 M_L |v_L|^2, over the located
/// points (element >= 0), with the same terms as the velocity update's own sums.
struct CompensatedKinetic {
  CompensatedReal solid, liquid;
};
CompensatedKinetic compensatedKineticEnergies(
    Kokkos::View<const int*, MemSpace> element_p, Kokkos::View<const int*, MemSpace> material_p,
    Kokkos::View<const int*, MemSpace> liquid_m, Kokkos::View<const Real*, MemSpace> mass_solid_p,
    Kokkos::View<const Real*, MemSpace> mass_liquid_p,
    Kokkos::View<const Real* [kDim], MemSpace> v_solid_p,
    Kokkos::View<const Real* [kDim], MemSpace> v_liquid_p);
/// sum over all points of `values` (e.g. M_L), reproducible.
CompensatedReal compensatedSum(Kokkos::View<const Real*, MemSpace> values);

/// At the listed nodes: hi = the sum of the parts (hi, lo) correctly rounded, lo = 0. Folding
/// after every reproducible P2G keeps lo zero everywhere for the next one (lo starts zero,
/// and a P2G touches active nodes only).
void foldCompensatedSums(const ActiveNodes& nodes, Kokkos::View<Real*, MemSpace> hi,
                         const LowParts<Kokkos::View<Real*, MemSpace>>& lo);
void foldCompensatedSums(const ActiveNodes& nodes, Kokkos::View<Real* [kDim], MemSpace> hi,
                         const LowParts<Kokkos::View<Real* [kDim], MemSpace>>& lo);
void foldCompensatedSums(const ActiveNodes& nodes, Kokkos::View<Real**, MemSpace> hi,
                         const LowParts<Kokkos::View<Real**, MemSpace>>& lo);
/// The same at every row (element) of `hi`.
void foldCompensatedSums(Kokkos::View<Real**, MemSpace> hi,
                         const LowParts<Kokkos::View<Real**, MemSpace>>& lo);

/// The low parts of one field of a struct of Views: lo[k].*field for every k.
template <class Fields, class View>
LowParts<View> lowPartsOf(const LowParts<Fields>& lo, View Fields::*field) {
  LowParts<View> out;
  for (int k = 0; k < kLowParts; ++k) out[k] = lo[k].*field;
  return out;
}

/// Allocates every low part as `like` (same label with a suffix, same extents).
template <class View>
LowParts<View> allocateLowParts(const View& like) {
  LowParts<View> lo;
  for (int k = 0; k < kLowParts; ++k)
    lo[k] = View(like.label() + "_lo" + std::to_string(k), like.layout());
  return lo;
}

}  // namespace argine
