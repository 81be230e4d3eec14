#pragma once
/// @file HydraulicAlgebra.hpp
/// The formulas of the hydraulic boundary conditions (thesis Sec. 4.1-4.3), one function
/// each, shared by the explicit solver's kernels and the unit tests:
///  - pressureOfHead: the total head (4.50) solved for the pressure;
///  - pressureSideForces / headSideForces: a pressure integrated along a straight side with
///    the linear edge shape functions, f_a = -n int N_a p dL (the load on the liquid (4.41)
///    and on the mixture (4.42));
///  - relativeFluxCorrection: the predictor-corrector of the infiltration (4.53-4.59) and
///    seepage-face conditions.
/// Signs: p_L compression positive; n the OUTWARD unit normal; a flux q_out = w . n > 0
/// leaves the soil (the deck's infiltration flux is q_in = -q_out).

#include "argine/core/Types.hpp"
#include "argine/input/Deck.hpp"

namespace argine {

/// p_L = rho_L g (H - y): (4.50) with h_g = y and compression positive (Pa).
KOKKOS_INLINE_FUNCTION Real pressureOfHead(Real rho_g, Real head, Real y) {
  return rho_g * (head - y);
}

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
    const Real q0 = below ? rule.below(y0) : rule.aboveLevel(y0);
    const Real q1 = below ? rule.below(y1) : rule.aboveLevel(y1);
    addPressurePieceForces(s0, s1, q0, q1, length, normal, fa, fb);
  };
  const bool crosses = (ya - H) * (yb - H) < 0;
  if (!crosses) return piece(0, 1);
  const Real cut = (H - ya) / (yb - ya);
  piece(0, cut);
  piece(cut, 1);
}

/// The velocity corrections of the infiltration (4.57-4.59) and seepage-face conditions at a
/// node: with the predicted velocities v_L~, v_S~, the liquid volume fraction n_L = n S_L,
/// the prescribed outward relative flux w^ . n = q_out, and
///   q_net = (n_L (v_L~ - v_S~) - w^) . n                                   (4.53)
///   dv_L  = -q_net n / (n_L (1 + m_L / m_S)),  dv_S = -m_L dv_L / m_S       (4.59, 4.58)
/// so that n_L (v_L - v_S) . n = q_out afterwards and the mixture momentum m_S v_S + m_L v_L
/// is unchanged. `solid_moves` false (fixed skeleton): dv_S = 0 and dv_L = -q_net n / n_L
/// (4.56). Returns q_net.
KOKKOS_INLINE_FUNCTION Real relativeFluxCorrection(Real n_liquid, Real mass_liquid, Real mass_solid,
                                                   bool solid_moves, const Real normal[kDim],
                                                   const Real velocity_liquid[kDim],
                                                   const Real velocity_solid[kDim], Real q_out,
                                                   Real dv_liquid[kDim], Real dv_solid[kDim]) {
  Real relative = 0;
  for (int d = 0; d < kDim; ++d) relative += (velocity_liquid[d] - velocity_solid[d]) * normal[d];
  const Real q_net = n_liquid * relative - q_out;  // 4.53
  const Real ratio = solid_moves && mass_solid > 0 ? mass_liquid / mass_solid : Real(0);
  const Real scale = -q_net / (n_liquid * (1 + ratio));  // 4.59
  for (int d = 0; d < kDim; ++d) {
    dv_liquid[d] = scale * normal[d];
    dv_solid[d] = -ratio * dv_liquid[d];  // 4.58
  }
  return q_net;
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
