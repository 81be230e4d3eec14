#pragma once
/// @file IntraElementSeepage.hpp
/// The Darcy flow between the material points of one element, which the grid cannot carry.
///
/// Why. The liquid momentum balance (4.36) sees the points' pressures only through the nodal
/// force sum_p V_p p_L,p grad N_i. On a linear triangle grad N_i is one vector per element, so
/// the grid sees one number per element, sum_p V_p p_L,p: any difference between the
/// pressures of the points of one element is invisible to it, drives no flow and is never
/// relaxed. The points of an element take nearly the same strain increment and flux, but not
/// the same storage: across the phreatic surface of the levee a saturated point stores
/// n / K_L = 5e-9 1/Pa and its unsaturated neighbour n (a_v + S_L/K_L) = 1.6e-7 1/Pa, 33 times
/// more. As a body slides, compression and drainage cycles push the two apart: measured in the
/// levee drawdown scene (issue P11), the saturated point of such an element climbs to +100 ..
/// +300 kPa while its neighbours sit at -3 .. -120 kPa, and the element's volume-weighted mean
/// stays at 6 .. 60 kPa, within the 65 kPa the overburden can hold. In the soil those points
/// are 0.1 m apart and the Darcy flow between them (k = 3.9e-4 m/s) equalises their
/// piezometric pressure in about a millisecond (saturated) or a few hundredths of a second
/// (unsaturated).
///
/// What. The points of an element exchange liquid through a common centre, each with the
/// Darcy conductance of its own sub-cell, g_p = k_p / g0 (kg/(Pa s) per m thickness: a
/// square sub-cell of side a passes (k/g0) (a/a) dphi from its centre to its edge; g0 = 9.81
/// m/s^2 the gravity k is defined with), driven by the piezometric pressure phi_p = p_L +
/// rho_L0 g y (thesis Eq. 4.50's total head times rho_L0 g). With the storage C_p = dM_L/dp_L
/// = n V rho_L (S_L/K_L - dS_L/ds) (4.12) the exchange is integrated implicitly over the step
/// (backward Euler on the star network, so it is stable for any dt and any storage):
///   phi_p^{k+1} = (phi_p + a_p phi_c) / (1 + a_p),   a_p = dt g_p / C_p,
///   dM_p = w_p (phi_c - phi_p),   w_p = dt g_p C_p / (C_p + dt g_p),
///   phi_c = sum_e w_p phi_p / sum_e w_p   (so sum_e dM_p = 0).
/// Each point moves towards the element's piezometric pressure at its own Darcy rate, time
/// scale C_p / g_p (levee, 0.2 m triangles: 0.8 ms saturated, 0.03 s unsaturated); a step
/// longer than that (w_p -> C_p) lands it there without overshoot. Properties:
///   - the liquid mass of every element, and so everything the grid sees of the liquid
///     content, is unchanged: only the distribution among the element's points changes;
///   - a hydrostatic state (phi uniform) is left alone;
///   - it is the sub-element seepage of the point's own material (k from its HCC), not a
///     tuned parameter; it acts on the pressure differences inside an element only, which
///     the one-pressure-per-element discretisation does not represent anyway.
/// `Locking Mitigation/Intra-Element Seepage` of the material switches it on (off: the thesis).
///
/// The patch (`Locking Mitigation/Seepage Patch`). `element` (the default) exchanges within
/// an element as above. `nodal` draws each point towards sum_i N_i(x_p) phi_i, phi_i =
/// sum_q N_i(x_q) w_q phi_q / sum_q N_i(x_q) w_q the w-weighted centre of node i's points
/// (PointValueAveraging's nodal mode), so points exchange with every point they share a node
/// with, across cell edges. Why: on a grid a shear band thins the points of a cell until one
/// is left alone in it; with `element` it exchanges with nobody. Measured on the grid levee
/// (uGIMP, 4 points a cell, element volumetric averaging, f = 0.75 on 0.1 m): a point alone
/// in its cell at the head scarp climbs from -5 to +119 kPa in 0.6 s after the slide stops,
/// its neighbours 2 cm away at -15 and -19 kPa. Still conservative (sum_p w_p sum_i N_i(x_p)
/// phi_i = sum_i phi_i sum_q N_i(x_q) w_q = sum_q w_q phi_q) and a convex relaxation (w_p <=
/// C_p: each point moves at most to its target, a weighted mean of the phi around it), but
/// explicit in the neighbours' values, not the exact implicit solution of the star.
/// The exchange enters the point mass balance as an extra flux divergence (PointRates), so the
/// outflow limit and the pressure update see it like any other flux.

#include "argine/core/Lanes.hpp"
#include "argine/core/Types.hpp"
#include "argine/physics/PointValueAveraging.hpp"

namespace argine {

class ActiveNodes;
class MaterialTable;
class NodalExchange;
struct MaterialPoints;
struct PointRates;
struct PointShapes;

/// w_p = dt g C / (C + dt g) (kg/Pa): the weight of a point of conductance g (kg/(Pa s)) and
/// storage C (kg/Pa) in the implicit star exchange over dt (file comment). C -> 0: C (the
/// point takes the centre's phi); g -> 0: dt g (the explicit Darcy exchange). T = Real, or
/// Lanes for kLanes points.
template <class T>
KOKKOS_INLINE_FUNCTION T starExchangeWeight(T conductance, T storage, Real dt) {
  const T flow = dt * conductance;
  return select(flow + storage > 0, flow * storage / (flow + storage), splat<T>(0));
}

class IntraElementSeepage {
 public:
  IntraElementSeepage() = default;
  /// Scratch for a mesh of `elements` elements and `nodes` nodes, allocated only when a
  /// material of `table` asks for the exchange. Elements belong to one MPI rank; on several
  /// ranks `exchange` completes the node sums of the nodal patch.
  IntraElementSeepage(const MaterialTable& table, int elements, int nodes,
                      NodalExchange* exchange = nullptr);

  bool active() const { return active_; }

  /// Adds the exchange of the step (file comment) to the flux divergences of `rates`
  /// (complete mass balance) or to the relative divergences (simplified), from the t^k state
  /// of the points (volume, porosity, p_L, S_L, k, position). `gravity` is the stage's
  /// (m/s^2, acting in -y).
  void apply(const MaterialTable& table, const MaterialPoints& points, const PointShapes& shapes,
             const ActiveNodes& active, PointRates& rates, Real dt, Real gravity);

  /// Reproducible sums (transfer/CompensatedSum.hpp): the element sums compensated.
  void compensateSums(bool on) { heads_.compensate(on); }

 private:
  /// Every exchanging material's patch the element (the levee decks), plain sums: the
  /// points add w phi and w to their element's sums as they compute them, and take the
  /// element's centre value as they exchange: the sums and quotients of averagePointValues
  /// in the same point order, so the same bits, in two passes over the points instead of
  /// four.
  void applyOverElements(const MaterialTable& table, const MaterialPoints& points,
                         PointRates& rates, Real dt, Real gravity);
  bool active_ = false;
  bool element_patches_ = false;       ///< every exchanging material's patch is its element
  NodalExchange* exchange_ = nullptr;  ///< several ranks: completes the nodal patch's sums
  /// One channel, the material's patch: weight w_p (0: not exchanged), value phi_p, then
  /// the centre value.
  AveragingScratch heads_;
};

}  // namespace argine
