#pragma once
/// @file HydraulicAlgebra.hpp
/// The formulas of the hydraulic boundary conditions (thesis Sec. 4.1-4.3), one function
/// each, shared by the explicit solver's kernels and the unit tests:
///  - pressureOfHead: the total head (4.50) solved for the pressure;
///  - pressureSideForces / headSideForces: a pressure integrated along a straight side with
///    the linear edge shape functions, f_a = -n int N_a p dL (the load on the liquid (4.41);
///    on the mixture (4.42) only its free-water part, mixtureLoadPressure);
///  - relativeFluxCorrection: the predictor-corrector of the infiltration (4.53-4.59) and
///    seepage-face conditions.
/// Signs: p_L compression positive; n the OUTWARD unit normal; a flux q_out = w . n > 0
/// leaves the soil (the deck's infiltration flux q is vertical rain: verticalRainOutwardFlux).

#include "argine/boundary/NodalConstraints.hpp"
#include "argine/core/Types.hpp"
#include "argine/input/Deck.hpp"

namespace argine {

/// p_L = rho_L g (H - y): (4.50) with h_g = y and compression positive (Pa).
KOKKOS_INLINE_FUNCTION Real pressureOfHead(Real rho_g, Real head, Real y) {
  return rho_g * (head - y);
}

/// The part of a prescribed liquid pressure p^ (Pa, compression positive) that loads the
/// MIXTURE (4.42) as a total traction -p n: max(p^, 0). The mixture's boundary term is the
/// total traction sigma n (4.35), set by what lies outside the soil: free water at p^ > 0
/// (the surface is saturated, S_L = 1, and sigma n = -p^ n: the water weight of Sec. 4.1),
/// or air at p = 0. A surface held at suction (p^ < 0) touches air: sigma n = 0, the
/// suction acts on the pore liquid only (it loads f_L^ext (4.41) in full) and its reaction
/// is in the skeleton (sigma' n = S_L p^ n by (4.5), compressive). Loading the mixture with
/// -p^ n, or -S_L(p^) p^ n (sigma' n = 0), would pull the surface outwards and break the
/// hydrostatic equilibrium of an unsaturated slope (sigma_yy = 0 at its surface).
KOKKOS_INLINE_FUNCTION Real mixtureLoadPressure(Real prescribed_pressure) {
  return prescribed_pressure > 0 ? prescribed_pressure : Real(0);
}

/// A total head's pressure as a field over the soil (`Hydraulic Loads: through the soil`,
/// physics/HeadLoadsThroughSoil.hpp): the liquid's p^(y) = pressureOfHead below the level and,
/// above it, 0 (seepage face, or a constant pressure of 0) or the same line continued
/// (linear suction); the mixture's is mixtureLoadPressure of it. Both are continuous in y, so
/// their gradients hold no jump a volume integral would miss.
struct HeadPressureField {
  Real rho_g = 0;              ///< rho_L g (Pa/m)
  Real head = 0;               ///< H (m)
  bool suction_above = false;  ///< linear suction above the level, else 0 there
  /// The liquid's p^ (Pa) and dp^/dy (Pa/m) at height y.
  KOKKOS_INLINE_FUNCTION void liquid(Real y, Real& p, Real& dp_dy) const {
    const bool loaded = y < head || suction_above;
    p = loaded ? pressureOfHead(rho_g, head, y) : Real(0);
    dp_dy = loaded ? -rho_g : Real(0);
  }
  /// The mixture's mixtureLoadPressure(p^) (Pa) and its derivative in y (Pa/m).
  KOKKOS_INLINE_FUNCTION void mixture(Real y, Real& p, Real& dp_dy) const {
    p = y < head ? mixtureLoadPressure(pressureOfHead(rho_g, head, y)) : Real(0);
    dp_dy = y < head ? -rho_g : Real(0);
  }
};

/// Adds to fa, fb (N per m thickness) the nodal forces of a pressure varying linearly from
/// q0 at s0 to q1 at s1 (0 <= s0 <= s1 <= 1 along the side a->b of length L, outward normal
/// n): f_a += -n L int_{s0}^{s1} (1 - s) p ds, f_b += -n L int s p ds. Simpson's rule, exact
/// for the quadratic integrand.
inline void addPressurePieceForces(Real s0, Real s1, Real q0, Real q1, Real length,
                                   const Real normal[kDim], Real fa[kDim], Real fb[kDim]) {
  const Real sm = 0.5 * (s0 + s1), qm = 0.5 * (q0 + q1), w = (s1 - s0) * length / 6;
  const Real ia = w * ((1 - s0) * q0 + 4 * (1 - sm) * qm + (1 - s1) * q1);
  const Real ib = w * (s0 * q0 + 4 * sm * qm + s1 * q1);
  for (int d = 0; d < kDim; ++d) {
    fa[d] -= normal[d] * ia;
    fb[d] -= normal[d] * ib;
  }
}

/// Nodal forces of a pressure linear from pa (node a) to pb (node b): f_a = -n L (2 pa +
/// pb) / 6, f_b = -n L (pa + 2 pb) / 6 (uniform p: -p n L / 2 each).
inline void pressureSideForces(Real pa, Real pb, Real length, const Real normal[kDim],
                               Real fa[kDim], Real fb[kDim]) {
  addPressurePieceForces(0, 1, pa, pb, length, normal, fa, fb);
}

/// What a total-head condition prescribes at elevation y for the current level H.
struct HeadPressureRule {
  Real rho_g = 9810;  ///< rho_L g (Pa/m)
  Real head = 0;      ///< H(t) (m)
  AboveLevel above = AboveLevel::ConstantPressure;
  Real pressure_above = 0;  ///< (Pa), AboveLevel::ConstantPressure
  /// true: the mixture's load, each pressure through mixtureLoadPressure (the suction above
  /// the level drops out); false: the liquid's load, the full pressure.
  bool mixture = false;
  /// p_L below (or at) the level, and above it by the rule; the seepage face is a natural
  /// zero-pressure boundary (its correction is separate).
  Real below(Real y) const { return pressureOfHead(rho_g, head, y); }
  Real aboveLevel(Real y) const {
    switch (above) {
      case AboveLevel::ConstantPressure:
        return pressure_above;
      case AboveLevel::LinearSuction:
        return pressureOfHead(rho_g, head, y);
      case AboveLevel::SeepageFace:
        return 0;
    }
    return 0;
  }
};

/// Nodal forces (added to fa, fb) of a total head on the side from xa to xb: the side is cut
/// at the level y = H into the part below (hydrostatic pressure) and the part above
/// (rule.aboveLevel); each part integrated exactly.
inline void headSideForces(const Real xa[kDim], const Real xb[kDim], Real length,
                           const Real normal[kDim], const HeadPressureRule& rule, Real fa[kDim],
                           Real fb[kDim]) {
  const Real ya = xa[1], yb = xb[1], H = rule.head;
  auto piece = [&](Real s0, Real s1) {
    const Real y0 = ya + s0 * (yb - ya), y1 = ya + s1 * (yb - ya);
    const bool below = 0.5 * (y0 + y1) <= H;
    Real q0 = below ? rule.below(y0) : rule.aboveLevel(y0);
    Real q1 = below ? rule.below(y1) : rule.aboveLevel(y1);
    if (rule.mixture) {  // exact: p has one sign on each piece (cut at the level)
      q0 = mixtureLoadPressure(q0);
      q1 = mixtureLoadPressure(q1);
    }
    addPressurePieceForces(s0, s1, q0, q1, length, normal, fa, fb);
  };
  const bool crosses = (ya - H) * (yb - H) < 0;
  if (!crosses) return piece(0, 1);
  const Real cut = (H - ya) / (yb - ya);
  piece(0, cut);
  piece(cut, 1);
}

/// The velocity corrections of the infiltration (4.57-4.59) and seepage-face conditions at a
/// node, from a MEASURED outward relative flux: with `measured` the predicted outward flux
/// per unit face length (m/s) and `fraction` its derivative along the normal,
/// d measured / d(w . n) (the liquid volume fraction n_L in the thesis form),
///   q_net = measured - q_out                                                (4.53)
///   dw    = -q_net n / fraction   (the relative velocity w = v_L - v_S that passes q_out)
///   dv_L  = dw / (1 + m_L / m_S),  dv_S = -m_L dv_L / m_S                    (4.59, 4.58)
/// so that the measured flux is q_out afterwards and the mixture momentum m_S v_S + m_L v_L is
/// unchanged. `solid_moves` false (fixed skeleton): dv_S = 0 and dv_L = dw (4.56).
///
/// `constraints` (NodalConstraintBits of the node): in a direction d where the solid is fixed
/// (kSolidFixedX/Y) the fixity, applied after the correction, removes dv_S,d again; there the
/// liquid takes the whole relative change, dv_L,d = dw_d and dv_S,d = 0, as on a fixed skeleton
/// (4.56), and the fixity's reaction takes the solid's share of the momentum. Split as in 4.59
/// instead, only dw_d / (1 + m_L / m_S) of it would survive, and a seepage face on a roller
/// (the river's face on the levee's axis, normal along the fixed x) would pass the fraction
/// (m_L / m_S) / (1 + m_L / m_S) (0.2 at n = 0.4, more as the points swell) of every inflow it
/// is meant to stop: in levee_rainfall the points beside the axis under the crest took that
/// water in and swelled from n = 0.40 to up to 0.63.
/// Returns q_net.
KOKKOS_INLINE_FUNCTION Real correctionOfMeasuredFlux(Real fraction, Real measured, Real mass_liquid,
                                                     Real mass_solid, bool solid_moves,
                                                     const Real normal[kDim], Real q_out,
                                                     Real dv_liquid[kDim], Real dv_solid[kDim],
                                                     unsigned constraints = 0u) {
  const Real q_net = measured - q_out;  // 4.53
  const Real ratio = solid_moves && mass_solid > 0 ? mass_liquid / mass_solid : Real(0);
  const Real scale = -q_net / (fraction * (1 + ratio));  // 4.59
  const Real fixed_scale = -q_net / fraction;            // 4.56: all of dw in the liquid
  for (int d = 0; d < kDim; ++d) {
    const bool fixed = (constraints & solidFixedBit(d)) != 0;
    dv_liquid[d] = (fixed ? fixed_scale : scale) * normal[d];
    dv_solid[d] = fixed ? Real(0) : -ratio * dv_liquid[d];  // 4.58
  }
  return q_net;
}

/// The thesis form (4.53-4.59): with the predicted velocities v_L~, v_S~ and the liquid
/// volume fraction n_L = n S_L, the measured flux is n_L (v_L~ - v_S~) . n, so that
/// n_L (v_L - v_S) . n = q_out afterwards. Returns q_net.
KOKKOS_INLINE_FUNCTION Real relativeFluxCorrection(Real n_liquid, Real mass_liquid, Real mass_solid,
                                                   bool solid_moves, const Real normal[kDim],
                                                   const Real velocity_liquid[kDim],
                                                   const Real velocity_solid[kDim], Real q_out,
                                                   Real dv_liquid[kDim], Real dv_solid[kDim],
                                                   unsigned constraints = 0u) {
  Real relative = 0;
  for (int d = 0; d < kDim; ++d) relative += (velocity_liquid[d] - velocity_solid[d]) * normal[d];
  return correctionOfMeasuredFlux(n_liquid, n_liquid * relative, mass_liquid, mass_solid,
                                  solid_moves, normal, q_out, dv_liquid, dv_solid, constraints);
}

/// The flux-weight form used by the solver: the node's outward liquid volume flux as the
/// point mass balance sees it is w . G_i / rho_L (G_i the flux weight, HydraulicBoundaryStep),
/// per unit face length |S_i| (S_i = sum of n L / 2 over the condition's sides at the node):
///   measured = w~ . G_i / (rho_L |S_i|).
/// After the correction the node passes exactly q_out |S_i| (m^2/s per m), so the liquid a
/// condition lets through is the prescribed one even where the points no longer fill the
/// elements (a deforming body: G_i is then not n_L rho_L S_i).
///
/// The correction acts along e = G_f / |G_f|, G_f = G_i without its components in the
/// directions where the liquid is locked to the solid (`constraints`, the node's
/// NodalConstraintBits: an impermeable lock, applied after the correction, would remove them
/// again; its solid fixities decide how dw is shared, correctionOfMeasuredFlux), with
///   fraction = e . G_i / (rho_L |S_i|) = |G_f| / (rho_L |S_i|).
/// w . G_i = q_out is a linear constraint on the relative velocity; its gradient is G_i, and
/// the correction along it (within the free directions) is the smallest change of w that
/// meets it: |dw| = |w~ . G_i / rho_L - q_out |S_i|| / |G_f|, never more than the relative
/// velocity itself when the target is zero (seepage face). For full Tri3 elements
/// G_i = rho_L n_L S_i, e = n and this is the thesis form (4.53-4.59). Correcting along the
/// side normal n instead (with fraction n . G_i / (rho_L |S_i|)) is an oblique projection:
/// where the body has deformed so that the free sides' normal is nearly perpendicular to G_i
/// (a crack opening in a sliding slope) it divides by n . G_i -> 0+ and gave a node of the
/// levee drawdown scene a relative velocity change of ~1000 m/s in one step.
/// Returns false (nothing set) when G_f = 0 (no liquid flux through the node in the free
/// directions): the caller uses the thesis form.
KOKKOS_INLINE_FUNCTION bool fluxWeightCorrection(
    const Real weight[kDim], Real density, Real face_length, Real mass_liquid, Real mass_solid,
    bool solid_moves, unsigned constraints, const Real velocity_liquid[kDim],
    const Real velocity_solid[kDim], Real q_out, Real dv_liquid[kDim], Real dv_solid[kDim],
    Real& q_net) {
  if (!(face_length > 0)) return false;
  const Real per_length = 1 / (density * face_length);
  Real direction[kDim], length2 = 0, measured = 0;
  for (int d = 0; d < kDim; ++d) {
    direction[d] = (constraints & liquidLockedBit(d)) ? Real(0) : weight[d];
    length2 += direction[d] * direction[d];
    measured += (velocity_liquid[d] - velocity_solid[d]) * weight[d] * per_length;
  }
  if (!(length2 > 0)) return false;
  const Real length = Kokkos::Experimental::sqrt(length2);
  for (int d = 0; d < kDim; ++d) direction[d] /= length;
  const Real fraction = length * per_length;  // e . G_i / (rho_L |S_i|)
  q_net = correctionOfMeasuredFlux(fraction, measured, mass_liquid, mass_solid, solid_moves,
                                   direction, q_out, dv_liquid, dv_solid, constraints);
  return true;
}

/// The prescribed outward relative flux w^ . n (m/s) of vertical rain of intensity q (m/s,
/// per unit HORIZONTAL area; rain positive, evaporation negative) on a surface of outward
/// unit normal n: w^ = (0, -q), so w^ . n = -q n_y. A side of length L then lets in
/// q n_y L = q times its horizontal projection, whatever the orientation of the sides that
/// represent the surface: a staircase of free sides on the background mesh receives the rain
/// of the surface it approximates (its vertical risers none), and a 45 degree face q L /
/// sqrt 2. Faces turned down (n_y <= 0) receive none: w^ . n = 0 there.
KOKKOS_INLINE_FUNCTION Real verticalRainOutwardFlux(Real q, const Real normal[kDim]) {
  return normal[1] > 0 ? -q * normal[1] : Real(0);
}

/// Kinds of nodal correction of one step.
enum class FluxCorrection : int {
  Infiltration = 0,         ///< correct when q_net < 0 (else zero pressure: ponding off)
  InfiltrationPonding = 1,  ///< always correct (ponding allowed)
  SeepageFace = 2,          ///< correct (to zero flux) only when the flux would enter
};

/// Whether a node of the given kind is corrected this step (the switch of Sec. 4.2 step 3
/// and of Sec. 4.3), q_net from relativeFluxCorrection: with ponding always; otherwise only
/// when q_net < 0, i.e. the zero-pressure prediction takes in more than prescribed (the
/// infiltration q_in = -q_out; for the seepage face q_out = 0: the liquid would enter).
/// q_net >= 0 keeps the natural zero-pressure condition: the saturated surface cannot take
/// the rain (it runs off), or liquid seeps out.
KOKKOS_INLINE_FUNCTION bool correctionApplies(int kind, Real q_net) {
  if (kind == static_cast<int>(FluxCorrection::InfiltrationPonding)) return true;
  return q_net < 0;
}

}  // namespace argine
