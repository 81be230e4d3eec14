#pragma once
/// @file MohrCoulomb.hpp
/// The return mapping of the elastic-perfectly plastic Mohr-Coulomb model with non-associated
/// flow and an optional tension cut-off, in principal stress space (Clausen, Damkilde and
/// Andersen 2006, 2007: "efficient return algorithms" for Mohr-Coulomb), plane strain with
/// sigma_zz as the third principal stress. One job: the stress update of one point; the
/// dispatch by model is in SolidModel.hpp.
///
/// Signs: tension positive. Principal stresses are sorted sigma_1 >= sigma_2 >= sigma_3, so
/// sigma_3 is the major COMPRESSIVE stress. With k = (1 + sin phi)/(1 - sin phi) and
/// m = (1 + sin psi)/(1 - sin psi) (N_phi and N_psi):
///   yield     F1 = k sigma_1 - sigma_3 - sigma_c <= 0,  sigma_c = 2 c sqrt(k)
///   potential G1 = m sigma_1 - sigma_3
///   apex      sigma_1 = sigma_2 = sigma_3 = sigma_a = sigma_c / (k - 1) = c cot phi
///   cut-off   T1 = sigma_1 - sigma_t <= 0 (associated), used only when sigma_t < sigma_a.
/// In compression-positive terms F1 = 0 is the familiar |sigma_3| = N_phi |sigma_1| +
/// 2 c sqrt(N_phi).
///
/// The surfaces are planes and the elastic stiffness in principal space is the constant
/// D_ij = lambda + 2 G delta_ij, so every return is exact (no iteration): for an active set A
/// of planes f_i = a_i . sigma - r_i with flow directions b_i,
///   sigma = sigma_B - sum_{j in A} dlambda_j D b_j,   a_i . sigma = r_i (i in A),
/// a linear system of size |A| <= 3. The active sets are tried in the order plane, edges
/// (triaxial compression sigma_1 = sigma_2: {F1, F2}; triaxial extension sigma_2 = sigma_3:
/// {F1, F3}), cut-off faces, corners; the first whose multipliers are >= 0 and whose stress
/// is admissible and still sorted is the return (the Kuhn-Tucker conditions; Clausen's
/// regions in principal space make it unique). When none is, the trial lies in the apex
/// region and the stress returns to the apex (sigma_a, or sigma_t on all three axes with
/// the cut-off). F2 = k sigma_2 - sigma_3 - sigma_c and F3 = k sigma_1 - sigma_2 - sigma_c
/// are the neighbouring planes of the sextant (sigma_1, sigma_2 or sigma_2, sigma_3
/// swapped).

#include <type_traits>

#include "argine/core/Types.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/materials/LinearElastic.hpp"
#include "argine/materials/MaterialParameters.hpp"

namespace argine {

/// Return regions of returnToMohrCoulomb (plastic_state values, see SolidModel.hpp).
inline constexpr int kMohrCoulombElastic = 0;  ///< trial admissible
inline constexpr int kMohrCoulombSurface = 1;  ///< Mohr-Coulomb plane or edge
inline constexpr int kMohrCoulombApex = 2;     ///< all three principal stresses equal
/// A face, edge or corner of the tension cut-off (with or without a Mohr-Coulomb plane): a
/// tensile crack, whose plastic strain opens it.
inline constexpr int kMohrCoulombTension = 3;

/// The strength of one point: c (Pa), phi and psi (rad), tension cut-off sigma_t (Pa).
struct MohrCoulombStrength {
  Real cohesion = 0;
  Real friction_angle = 0;
  Real dilatancy_angle = 0;
  Real tensile_strength = 0;
  bool tension_cutoff = false;
};

/// N = (1 + sin a)/(1 - sin a): k for the friction angle, m for the dilatancy angle.
KOKKOS_INLINE_FUNCTION Real flowFactor(Real angle) {
  const Real s = kmath::sin(angle);
  return (1 + s) / (1 - s);
}

/// Apex stress sigma_a = 2 c sqrt(k) / (k - 1) = c cot phi (Pa, tension positive); +infinity
/// for phi = 0 (Tresca: no apex).
KOKKOS_INLINE_FUNCTION Real mohrCoulombApex(const MohrCoulombStrength& s) {
  const Real k = flowFactor(s.friction_angle);
  if (k <= 1) return kmath::infinity();
  return 2 * s.cohesion * kmath::sqrt(k) / (k - 1);
}

/// F1 = k sigma_1 - sigma_3 - 2 c sqrt(k) (Pa) of SORTED principal stresses (> 0: outside).
KOKKOS_INLINE_FUNCTION Real mohrCoulombYield(const MohrCoulombStrength& s, const Real sigma[3]) {
  const Real k = flowFactor(s.friction_angle);
  return k * sigma[0] - sigma[2] - 2 * s.cohesion * kmath::sqrt(k);
}

/// What the return mapping derives from a strength: k, m, sigma_c = 2 c sqrt(k) and the apex
/// sigma_a, each by the expression of the functions above (same values to the bit). A
/// material whose strength does not depend on suction derives them once (SolidConstants,
/// SolidModel.hpp) instead of at every point: the sines are most of an elastic point's cost.
struct MohrCoulombFactors {
  Real k = 1;                     ///< N_phi = (1 + sin phi)/(1 - sin phi)
  Real m = 1;                     ///< N_psi = (1 + sin psi)/(1 - sin psi)
  Real sigma_c = 0;               ///< 2 c sqrt(k) (Pa)
  Real apex = kmath::infinity();  ///< sigma_a = sigma_c / (k - 1), +infinity for k <= 1 (Pa)
};

/// The factors of strength `s` whose flow factors k = N_phi and m = N_psi are known already
/// (those of s's angles: a suction-dependent cohesion with constant angles, SolidModel.hpp).
KOKKOS_INLINE_FUNCTION MohrCoulombFactors mohrCoulombFactors(const MohrCoulombStrength& s, Real k,
                                                             Real m) {
  MohrCoulombFactors f;
  f.k = k;
  f.m = m;
  f.sigma_c = 2 * s.cohesion * kmath::sqrt(f.k);
  f.apex = f.k <= 1 ? kmath::infinity() : f.sigma_c / (f.k - 1);
  return f;
}

KOKKOS_INLINE_FUNCTION MohrCoulombFactors mohrCoulombFactors(const MohrCoulombStrength& s) {
  return mohrCoulombFactors(s, flowFactor(s.friction_angle), flowFactor(s.dilatancy_angle));
}

namespace mc_detail {

/// One plane of the yield surface in principal space: f = a . sigma - r, flow direction b.
struct Plane {
  Real a[3];
  Real b[3];
  Real r;
};

/// The planes F1, F2, F3, T1, T2, T3 (file comment) in this order.
enum PlaneId { kF1 = 0, kF2, kF3, kT1, kT2, kT3, kPlaneCount };

KOKKOS_INLINE_FUNCTION void makePlanes(const MohrCoulombStrength& s, const MohrCoulombFactors& f,
                                       Plane planes[kPlaneCount]) {
  const Real k = f.k;
  const Real m = f.m;
  const Real sc = f.sigma_c;
  const Plane f1 = {{k, 0, -1}, {m, 0, -1}, sc};
  const Plane f2 = {{0, k, -1}, {0, m, -1}, sc};
  const Plane f3 = {{k, -1, 0}, {m, -1, 0}, sc};
  const Plane t1 = {{1, 0, 0}, {1, 0, 0}, s.tensile_strength};
  const Plane t2 = {{0, 1, 0}, {0, 1, 0}, s.tensile_strength};
  const Plane t3 = {{0, 0, 1}, {0, 0, 1}, s.tensile_strength};
  planes[kF1] = f1;
  planes[kF2] = f2;
  planes[kF3] = f3;
  planes[kT1] = t1;
  planes[kT2] = t2;
  planes[kT3] = t3;
}

/// D v in principal space: lambda (v1 + v2 + v3) + 2 G v_i.
KOKKOS_INLINE_FUNCTION void applyStiffness(Real lambda, Real two_g, const Real v[3], Real out[3]) {
  const Real trace = v[0] + v[1] + v[2];
  for (int i = 0; i < 3; ++i) out[i] = lambda * trace + two_g * v[i];
}

/// Solves the n x n system A x = y (n <= 3) by Gaussian elimination with partial pivoting;
/// false when singular (relative pivot below 1e-12). n is a template parameter so that each
/// size's loops unroll (the return is most of a plastic point's cost).
template <int n>
KOKKOS_INLINE_FUNCTION bool solveSmall(Real A[3][3], Real y[3], Real x[3]) {
  Real scale = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) scale = kmath::fmax(scale, kmath::fabs(A[i][j]));
  if (!(scale > 0)) return false;
  for (int c = 0; c < n; ++c) {
    int pivot = c;
    for (int i = c + 1; i < n; ++i)
      if (kmath::fabs(A[i][c]) > kmath::fabs(A[pivot][c])) pivot = i;
    if (kmath::fabs(A[pivot][c]) < 1e-12 * scale) return false;
    if (pivot != c) {
      for (int j = 0; j < n; ++j) {
        const Real t = A[c][j];
        A[c][j] = A[pivot][j];
        A[pivot][j] = t;
      }
      const Real t = y[c];
      y[c] = y[pivot];
      y[pivot] = t;
    }
    for (int i = c + 1; i < n; ++i) {
      const Real factor = A[i][c] / A[c][c];
      for (int j = c; j < n; ++j) A[i][j] -= factor * A[c][j];
      y[i] -= factor * y[c];
    }
  }
  for (int i = n - 1; i >= 0; --i) {
    Real sum = y[i];
    for (int j = i + 1; j < n; ++j) sum -= A[i][j] * x[j];
    x[i] = sum / A[i][i];
  }
  return true;
}

/// Tries the return to the active set `ids` (n planes); on success (multipliers >= 0, F1
/// and, with the cut-off, T1 satisfied, order kept) writes the returned stress to `out`.
template <int n>
KOKKOS_INLINE_FUNCTION bool tryActiveSet(const Plane planes[kPlaneCount], const int ids[3],
                                         Real lambda, Real two_g, bool cutoff, Real tolerance,
                                         const Real trial[3], Real out[3]) {
  Real Db[3][3];  // D b_j of the active planes
  for (int j = 0; j < n; ++j) applyStiffness(lambda, two_g, planes[ids[j]].b, Db[j]);
  Real A[3][3], y[3], x[3];
  for (int i = 0; i < n; ++i) {
    const Plane& plane = planes[ids[i]];
    y[i] = plane.a[0] * trial[0] + plane.a[1] * trial[1] + plane.a[2] * trial[2] - plane.r;
    for (int j = 0; j < n; ++j)
      A[i][j] = plane.a[0] * Db[j][0] + plane.a[1] * Db[j][1] + plane.a[2] * Db[j][2];
  }
  if (!solveSmall<n>(A, y, x)) return false;
  // Kuhn-Tucker: dlambda_j >= 0, measured as a stress (dlambda (lambda + 2G)).
  for (int j = 0; j < n; ++j)
    if (x[j] * (lambda + two_g) < -tolerance) return false;
  for (int c = 0; c < 3; ++c) {
    out[c] = trial[c];
    for (int j = 0; j < n; ++j) out[c] -= x[j] * Db[j][c];
  }
  if (out[0] < out[1] - tolerance || out[1] < out[2] - tolerance) return false;
  const Plane& f1 = planes[kF1];
  if (f1.a[0] * out[0] + f1.a[2] * out[2] - f1.r > tolerance) return false;
  if (cutoff && out[0] - planes[kT1].r > tolerance) return false;
  return true;
}

}  // namespace mc_detail

/// The admissibility test of returnToMohrCoulomb for SORTED principal trial stresses: the
/// tension cut-off where it matters, the tolerance of every test of the return (1e-12 x the
/// stress scale), and whether the trial lies outside the surface (F1 or, with the cut-off,
/// T1 above the tolerance). One place, so that a caller may test before calling the return.
/// T = Real for one point, Lanes for kLanes points (core/Lanes.hpp; `outside` is then a
/// LaneMask).
template <class T>
struct MohrCoulombTrialCheck {
  bool cutoff;
  T tolerance;
  decltype(T{} > T{}) outside;
};

template <class T>
KOKKOS_INLINE_FUNCTION MohrCoulombTrialCheck<T> checkMohrCoulombTrial(
    const MohrCoulombStrength& strength, const MohrCoulombFactors& factors, const T sigma[3]) {
  MohrCoulombTrialCheck<T> check;
  // The cut-off matters only below the apex (F1 <= 0 in the sextant implies sigma_1 <= sigma_a).
  check.cutoff = strength.tension_cutoff && strength.tensile_strength < factors.apex;
  const T scale = kmath::fabs(sigma[0]) + kmath::fabs(sigma[1]) + kmath::fabs(sigma[2]) +
                  strength.cohesion +
                  (check.cutoff ? kmath::fabs(strength.tensile_strength) : Real(0));
  check.tolerance = 1e-12 * select(scale > 0, scale, splat<T>(1));
  const T yield = factors.k * sigma[0] - sigma[2] - factors.sigma_c;  // mohrCoulombYield
  check.outside = yield > check.tolerance;
  if (check.cutoff)
    check.outside = either(check.outside, sigma[0] - strength.tensile_strength > check.tolerance);
  return check;
}

/// Returns the SORTED principal trial stresses sigma (sigma[0] >= sigma[1] >= sigma[2], Pa)
/// to the Mohr-Coulomb surface in place (file comment); lambda, G the elastic constants,
/// `factors` = mohrCoulombFactors(strength). Writes the principal plastic strain increment
/// D^-1 (sigma_trial - sigma) to plastic_strain and returns the region (kMohrCoulombElastic,
/// Surface, Apex or Tension).
KOKKOS_INLINE_FUNCTION int returnToMohrCoulomb(const MohrCoulombStrength& strength,
                                               const MohrCoulombFactors& factors, Real lambda,
                                               Real shear_modulus, Real sigma[3],
                                               Real plastic_strain[3]) {
  using namespace mc_detail;
  for (int c = 0; c < 3; ++c) plastic_strain[c] = 0;
  const Real apex = factors.apex;
  const MohrCoulombTrialCheck<Real> check = checkMohrCoulombTrial(strength, factors, sigma);
  if (!check.outside) return kMohrCoulombElastic;
  const bool cutoff = check.cutoff;
  const Real tolerance = check.tolerance;

  Plane planes[kPlaneCount];
  makePlanes(strength, factors, planes);
  const Real two_g = 2 * shear_modulus;
  // Active sets in the order of the file comment; -1 ends a set.
  constexpr int kSets = 12;
  constexpr int sets[kSets][3] = {
      {kF1, -1, -1},   {kF1, kF2, -1},  {kF1, kF3, -1},    // MC plane, edges
      {kT1, -1, -1},   {kF1, kT1, -1},  {kT1, kT2, -1},    // cut-off face, edges
      {kF1, kF3, kT1}, {kF1, kF2, kT1}, {kF1, kT1, kT2},   // corners sigma_1 = sigma_t
      {kF2, kT1, kT2}, {kF1, kF2, kT2}, {kT1, kT2, kT3}};  // (Caratheodory subsets), tension apex
  const int last = cutoff ? kSets : 3;
  Real trial[3] = {sigma[0], sigma[1], sigma[2]};
  Real out[3];
  bool found = false;
  int region = kMohrCoulombSurface;
  for (int s = 0; s < last && !found; ++s) {
    int n = 0;
    while (n < 3 && sets[s][n] >= 0) ++n;
    const auto tryIt = [&](auto size) {
      return tryActiveSet<decltype(size)::value>(planes, sets[s], lambda, two_g, cutoff, tolerance,
                                                 trial, out);
    };
    found = n == 1   ? tryIt(std::integral_constant<int, 1>{})
            : n == 2 ? tryIt(std::integral_constant<int, 2>{})
                     : tryIt(std::integral_constant<int, 3>{});
    if (found && s >= 3) region = kMohrCoulombTension;  // the sets with a cut-off plane
    if (found && n == 3 && sets[s][0] == kT1 && sets[s][2] == kT3) region = kMohrCoulombApex;
  }
  if (!found) {  // apex region: MC apex, or with the cut-off all three at sigma_t
    const Real corner = cutoff ? strength.tensile_strength : apex;
    for (int c = 0; c < 3; ++c) out[c] = corner;
    region = kMohrCoulombApex;
  }
  // d eps^p = D^-1 (sigma_B - sigma): D^-1 v = v / 2G - lambda tr(v) / (2G (3 lambda + 2G)).
  Real dsigma[3];
  for (int c = 0; c < 3; ++c) dsigma[c] = trial[c] - out[c];
  const Real trace = dsigma[0] + dsigma[1] + dsigma[2];
  for (int c = 0; c < 3; ++c) {
    plastic_strain[c] = dsigma[c] / two_g - lambda * trace / (two_g * (3 * lambda + two_g));
    sigma[c] = out[c];
  }
  return region;
}

/// The same, deriving the factors from `strength`.
KOKKOS_INLINE_FUNCTION int returnToMohrCoulomb(const MohrCoulombStrength& strength, Real lambda,
                                               Real shear_modulus, Real sigma[3],
                                               Real plastic_strain[3]) {
  return returnToMohrCoulomb(strength, mohrCoulombFactors(strength), lambda, shear_modulus, sigma,
                             plastic_strain);
}

/// In-plane principal decomposition of (xx, yy, xy): centre c, radius R >= 0 and the unit
/// direction (cos 2 theta, sin 2 theta) of the major axis (1, 0 when R = 0). The principal
/// values are c + R and c - R. T = Real, or Lanes for kLanes points (core/Lanes.hpp).
template <class T>
struct InPlanePrincipal {
  T centre;
  T radius;
  T half_difference;  ///< (xx - yy) / 2
  T shear;            ///< xy

  /// cos 2 theta, sin 2 theta: two divisions, so only asked for where a return rotates the
  /// principal values back (an elastic point keeps its trial stress). One point.
  KOKKOS_INLINE_FUNCTION void direction(Real& cos2, Real& sin2) const {
    const Real tiny = 1e-300;
    if (radius > tiny) {
      cos2 = half_difference / radius;
      sin2 = shear / radius;
    } else {
      cos2 = 1;
      sin2 = 0;
    }
  }
};

template <class T>
KOKKOS_INLINE_FUNCTION InPlanePrincipal<T> inPlanePrincipal(T xx, T yy, T xy) {
  InPlanePrincipal<T> p;
  p.centre = (xx + yy) / 2;
  p.half_difference = (xx - yy) / 2;
  p.shear = xy;
  p.radius = kmath::sqrt(p.half_difference * p.half_difference + xy * xy);
  return p;
}

/// The plane-strain principal stresses of a trial stress (xx, yy, zz, xy) sorted descending
/// into sigma[0] >= sigma[1] >= sigma[2]: the in-plane pair c + R, c - R and sigma_zz. Returns
/// where sigma_zz went (slot 0, 1 or 2; with Lanes, per lane). Ties put sigma_zz first.
template <class T>
KOKKOS_INLINE_FUNCTION auto sortedPrincipalStresses(const InPlanePrincipal<T>& in_plane, T zz,
                                                    T sigma[3]) {
  const T major = in_plane.centre + in_plane.radius;
  const T minor = in_plane.centre - in_plane.radius;
  const auto first = zz >= major, second = zz >= minor;  // zz in slot 0, or in slot 1 or 0
  sigma[0] = select(first, zz, major);
  sigma[1] = select(first, major, select(second, zz, minor));
  sigma[2] = select(either(first, second), minor, zz);
  if constexpr (std::is_same_v<T, Real>)
    return first ? 0 : second ? 1 : 2;
  else
    return 0;  // not needed by the Lanes caller, which returns plastic lanes one by one
}

/// Equivalent deviatoric strain sqrt(2/3 e:e) of principal strains.
KOKKOS_INLINE_FUNCTION Real equivalentPrincipalDeviatoric(const Real e[3]) {
  const Real mean = (e[0] + e[1] + e[2]) / 3;
  const Real d0 = e[0] - mean, d1 = e[1] - mean, d2 = e[2] - mean;
  return kmath::sqrt(2.0 / 3.0 * (d0 * d0 + d1 * d1 + d2 * d2));
}

/// The Mohr-Coulomb update of one point in plane strain: elastic trial sigma + D d eps, its
/// principal values (in-plane pair and sigma_zz), the return of returnToMohrCoulomb, and back
/// to xx, yy, zz, xy with the trial's principal directions. `plastic_strain` grows by the
/// equivalent deviatoric plastic strain sqrt(2/3 e^p:e^p) of the increment. Returns the
/// region (plastic_state). lambda, G the elastic constants (Pa), `factors` =
/// mohrCoulombFactors(strength).
KOKKOS_INLINE_FUNCTION int mohrCoulombStressUpdate(Real lambda, Real shear_modulus,
                                                   const MohrCoulombStrength& strength,
                                                   const MohrCoulombFactors& factors,
                                                   const Real dstrain[kStressComponents],
                                                   Real stress[kStressComponents],
                                                   Real& plastic_strain) {
  Real dstress[kStressComponents];
  elasticStressIncrement(lambda, 2 * shear_modulus, dstrain, dstress);
  Real trial[kStressComponents];
  for (int i = 0; i < kStressComponents; ++i) trial[i] = stress[i] + dstress[i];
  const InPlanePrincipal<Real> in_plane = inPlanePrincipal(trial[0], trial[1], trial[3]);
  Real sigma[3];
  const int z_slot = sortedPrincipalStresses(in_plane, trial[2], sigma);
  // Most points are inside the surface: test here, and call the return (large, not inlined)
  // only for the others.
  if (!checkMohrCoulombTrial(strength, factors, sigma).outside) {
    for (int i = 0; i < kStressComponents; ++i) stress[i] = trial[i];
    return kMohrCoulombElastic;
  }
  Real plastic[3];
  const int region = returnToMohrCoulomb(strength, factors, lambda, shear_modulus, sigma, plastic);
  Real new_major, new_minor, new_zz;
  if (z_slot == 0) {
    new_zz = sigma[0], new_major = sigma[1], new_minor = sigma[2];
  } else if (z_slot == 1) {
    new_major = sigma[0], new_zz = sigma[1], new_minor = sigma[2];
  } else {
    new_major = sigma[0], new_minor = sigma[1], new_zz = sigma[2];
  }
  const Real centre = (new_major + new_minor) / 2, radius = (new_major - new_minor) / 2;
  Real cos2, sin2;
  in_plane.direction(cos2, sin2);
  stress[0] = centre + radius * cos2;
  stress[1] = centre - radius * cos2;
  stress[2] = new_zz;
  stress[3] = radius * sin2;
  plastic_strain += equivalentPrincipalDeviatoric(plastic);
  return region;
}

/// The same with the elastic constants of `spec` and the factors of `strength`.
KOKKOS_INLINE_FUNCTION int mohrCoulombStressUpdate(const SolidSpec& spec,
                                                   const MohrCoulombStrength& strength,
                                                   const Real dstrain[kStressComponents],
                                                   Real stress[kStressComponents],
                                                   Real& plastic_strain) {
  return mohrCoulombStressUpdate(lameLambda(spec), shearModulus(spec), strength,
                                 mohrCoulombFactors(strength), dstrain, stress, plastic_strain);
}

}  // namespace argine
