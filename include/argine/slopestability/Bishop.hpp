#pragma once
/// @file Bishop.hpp
/// Factors of safety of a sliced circular surface by moment equilibrium about the centre
/// (on a non-circular surface these formulas are not an equilibrium: use Spencer.hpp):
///  - Bishop's simplified method (Bishop 1955): interslice shear neglected, vertical force
///    equilibrium of each slice,
///      F = sum[(c' b + (W - u b) tan phi') / m_alpha] / sum[W sin alpha],
///      m_alpha = cos(alpha) (1 + tan(alpha) tan(phi') / F),
///    solved by fixed-point iteration on F;
///  - the ordinary method of slices (Fellenius 1936): all interslice forces neglected,
///      F = sum[c' l + (W cos(alpha) - u l) tan phi'] / sum[W sin alpha],  l = b / cos(alpha).
/// Both use the positive part of u: negative pore pressure is not counted as strength through
/// u; matric suction enters only through Slice::suction_strength, added to c' as an apparent
/// cohesion (c' -> c' + S in both formulas). A mass that slides towards +x
/// (sum W sin alpha < 0) is handled by mirroring (alpha -> -alpha).

#include <vector>

#include "argine/core/Types.hpp"
#include "argine/slopestability/Slice.hpp"

namespace argine {

/// Settings of Bishop's iteration.
struct BishopOptions {
  Real tolerance = 1e-8;  ///< stop when |F_{k+1} - F_k| <= tolerance F_k
  int max_iterations = 200;
  Real initial_guess = 0;  ///< <= 0: start from the ordinary method's F
  /// Smallest admissible m_alpha at the converged F. Below it the normal force on the base of
  /// a steep toe slice becomes unrealistically large (or negative) and F meaningless;
  /// 0.2 after Whitman & Bailey (1967), the limit Duncan & Wright (2005, Ch. 6) recommend.
  Real min_m_alpha = 0.2;
};

/// A factor of safety and how it was obtained.
struct FactorOfSafety {
  Real value = 0;           ///< F
  bool admissible = false;  ///< false: no driving moment, m_alpha guard hit, or no convergence
  bool converged = false;   ///< Bishop: the iteration met the tolerance (ordinary: always true)
  int iterations = 0;
  Real min_m_alpha = 0;  ///< smallest m_alpha of the slices at F (Bishop)
  Real driving = 0;      ///< sum W sin alpha (N/m, after mirroring: >= 0)
};

/// m_alpha = cos(alpha) (1 + tan(alpha) tan(phi') / F).
Real bishopMAlpha(Real alpha, Real friction_angle, Real factor);

/// Bishop's simplified factor of safety of `slices` (see the file comment).
/// `external_driving` (N/m): horizontal forces' moment about the centre divided by R, in the
/// sense of sum W sin(alpha) (endForceDriving of CircularSlip.hpp), added to the driving sum.
FactorOfSafety bishopSimplified(const std::vector<Slice>& slices, const BishopOptions& options = {},
                                Real external_driving = 0);

/// The ordinary (Fellenius) factor of safety of `slices`; for cross-checking.
FactorOfSafety ordinaryMethodOfSlices(const std::vector<Slice>& slices, Real external_driving = 0);

}  // namespace argine
