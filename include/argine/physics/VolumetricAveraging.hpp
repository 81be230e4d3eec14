#pragma once
/// @file VolumetricAveraging.hpp
/// Volumetric-locking and cell-crossing mitigation (thesis Ch. 4 Sec. 5; SPEC "strain
/// smoothing (nodal mixed discretisation) or element-averaged ... (MPM-MIXED)"). Low-order
/// elements crossed by several material points cannot follow a point-wise incompressible or
/// plastically dilating volume change: the pressure and mean stress oscillate from point to
/// point (locking, checkerboard). The remedy replaces the volumetric part of each point's
/// increment by a smoothed one, per material (`Locking Mitigation` in the deck):
///
///   element  q_p <- sum_{q in e} w_q q_q / sum_{q in e} w_q  over the points of the point's
///            element e that use the same averaging (MPM-MIXED style);
///   nodal    q_i = sum_p N_i(x_p) w_p q_p / sum_p N_i(x_p) w_p at the nodes, then
///            q_p <- sum_i N_i(x_p) q_i (nodal mixed discretisation).
///
/// Solid: q = d eps_vol = d eps_xx + d eps_yy (plane strain, d eps_zz = 0), w = V. The
/// smoothed value is put back through d eps_xx and d eps_yy in equal parts (the in-plane
/// deviatoric part and d eps_zz = 0 unchanged). At liquid-carrying points the relative
/// divergence dt div(v_L - v_S) and the flux divergence dt div(c w) of the mass balance get the
/// same averaging, so both phases see one smoothing operator (smoothing the solid alone gives
/// a non-symmetric phase coupling that the explicit step amplifies). Both weightings keep
/// sum V q, the change of the element (element) or of the body (nodal): volume and liquid
/// mass are conserved.
///
/// Liquid: q = d p_L of the step at liquid-carrying points, w = the point's storage over the
/// step, n V Delta(S_L rho_L) / d p_L (4.12; ~ n V rho_L / K_L when saturated), so that
/// w d p_L is the liquid mass the increment stores (pressureAveragingWeight).
///   saturated material: rho_L from (4.13) and M_L = n rho_L V; sum w d p_L is kept, so the
///     liquid mass is kept to first order in d p_L / K_L.
///   unsaturated material: M_L <- M_L + w (averaged d p_L - own d p_L) (the mass follows the
///     pressure increment it is given: sum M_L is kept exactly), then p_L, rho_L, S_L, k from
///     that mass as in the mass balance (LiquidState.hpp). Without it, the points of a Tri3
///     element, which share one flux divergence, all carry the element's p_L: a profile
///     with a gradient (hydrostatic, rho_L g) is then off by rho_L g |y_p - y_centroid| at
///     every point (the V3 infiltration column: 170 Pa, 8.8 % of the range, doc/verification.md).
///     The storage weight makes a nearly saturated point (storage ~ n V rho_L / K_L) take the
///     pressure of its unsaturated neighbours rather than their liquid mass.

#include "argine/core/Types.hpp"
#include "argine/physics/LiquidState.hpp"

namespace argine {

/// Weight of a point's pressure increment from `before` to `after` in the liquid-pressure
/// averaging: its storage n V [S_L rho_L](after) - [S_L rho_L](before)) / (after - before)
/// (kg/Pa per m), the liquid mass the increment stores at constant n V (4.12, 4.13). The
/// secant, not the tangent: an increment across the saturation kink (s = 0), where the
/// storage drops from n V rho_L dS_L/ds to n V rho_L / K_L, is weighted by what it stored.
/// Increments below 1e-6 Pa take the tangent n V rho_L (S_L/K_L - dS_L/ds) at `before`.
KOKKOS_INLINE_FUNCTION Real pressureAveragingWeight(const PointMaterial& material, Real porosity,
                                                    Real volume, Real before, Real after) {
  const Real pore_volume = porosity * volume;
  const LiquidState old_state = liquidState(material, before);
  const Real old_density = liquidDensity(material.liquid, before);
  if (!(kmath::fabs(after - before) > 1e-6))
    return pore_volume * liquidContentSlope(old_density, old_state.saturation,
                                            old_state.saturation_suction_derivative,
                                            material.liquid.bulk_modulus);
  const Real new_content =
      saturationAndConductivity(material, after).saturation * liquidDensity(material.liquid, after);
  return pore_volume * (new_content - old_state.saturation * old_density) / (after - before);
}

/// Liquid mass of a point after the averaging replaced its pressure increment `own` by
/// `averaged`: M_L + w (averaged - own), w = pressureAveragingWeight. The sum over the
/// averaged points is unchanged, as sum w averaged = sum w own (file comment).
KOKKOS_INLINE_FUNCTION Real averagedLiquidMass(Real mass, Real weight, Real own, Real averaged) {
  return mass + weight * (averaged - own);
}

class ActiveNodes;
class MaterialTable;
struct MaterialPoints;
struct PointRates;
struct PointShapes;

class VolumetricAveraging {
 public:
  VolumetricAveraging() = default;
  /// Scratch for a mesh of `elements` elements and `nodes` nodes, allocated only when a
  /// material of `table` asks for an averaging.
  VolumetricAveraging(const MaterialTable& table, int elements, int nodes);

  /// Whether any material averages the volumetric strain / the liquid pressure increment.
  bool averagesStrain() const { return strain_; }
  bool averagesPressure() const { return pressure_; }

  /// Replaces d eps_vol of the points whose material asks for it (file comment). `active`
  /// holds the nodes of the points' elements.
  void averageStrainIncrements(const MaterialTable& table, const MaterialPoints& points,
                               const PointShapes& shapes, const ActiveNodes& active,
                               PointRates& rates);
  /// Keeps p_L of every point before the liquid mass balance of the step.
  void rememberPressures(const MaterialPoints& points);
  /// After the mass balance: averages d p_L = p_L - remembered p_L of the liquid-carrying
  /// points whose material asks for it; rho_L and M_L (and S_L, k: unsaturated) follow.
  void averagePressureIncrements(const MaterialTable& table, const MaterialPoints& points,
                                 const PointShapes& shapes, const ActiveNodes& active);

 private:
  bool strain_ = false;
  bool pressure_ = false;
  Kokkos::View<Real*, MemSpace> value_point_;       ///< per point: the quantity, then its average
  Kokkos::View<Real*, MemSpace> weight_point_;      ///< per point: its weight (0: not averaged)
  Kokkos::View<int*, MemSpace> mode_point_;         ///< per point: IncrementAveraging as int
  Kokkos::View<Real*, MemSpace> old_pressure_;      ///< p_L before the step
  Kokkos::View<Real* [2], MemSpace> element_sums_;  ///< sum w q, sum w per element
  Kokkos::View<Real* [2], MemSpace> node_sums_;     ///< sum N w q, sum N w per node
};

}  // namespace argine
