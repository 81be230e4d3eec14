#pragma once
/// @file LiquidHeadStabilisation.hpp
/// Stabilisation of the explicit liquid mass balance against the Tri3 pressure checkerboard.
///
/// Why. On linear triangles each element carries one liquid pressure (its points share one
/// flux divergence), and the nodal liquid force sum_p V_p grad N_i p_p cannot see a pattern
/// that alternates between the "up" and "down" triangles of a structured mesh: the P1-P0
/// spurious pressure mode. In the saturated zone, where the storage n S_L rho_L / K_L is tiny,
/// any uneven inflow (a wetting front reaching the water table element by element, a river
/// rising on a staircase boundary) is stored as such a pattern and nothing removes it: on
/// V4 neighbouring elements under the riverside slope differ by 11 kPa against a 6 kPa
/// hydrostatic mean (doc/verification.md V4).
///
/// What. A pressure-jump stabilisation in the spirit of Brezzi-Pitkaranta / Silvester-Kechkar
/// for P1-P0, written as a conservative exchange of liquid mass through the nodes. With the
/// piezometric pressure phi_p = p_L + rho_L0 g y of each point and its conductance
///   g_p = min(alpha k_p / g0, share storage_p / dt)   (kg/(Pa s)),
/// g0 = 9.81 m/s^2 the gravity the conductivity k (m/s) is defined with, and storage_p =
/// n V rho_L (S_L/K_L - dS_L/ds) the point's dM_L/dp_L, each node has a centre, the
/// N_i g_p-weighted means m_i of phi and x_i of x over its points, and a slope b_i, the
/// N_i g_p-weighted mean over its points of G_p, the gradient of the plane through the centres
/// of the point's nodes (least squares with the weights N_i(x_p); on a triangle the plane
/// through its three centres). Each point's liquid mass changes by
///   dM_p = -dt g_p (phi_p - sum_i N_i(x_p) (m_i + b_i . (x_p - x_i))).
/// Properties:
///   - sum_p dM_p = 0: sum_p g_p sum_i N_i(x_p) (m_i + b_i . (x_p - x_i)) = sum_p g_p phi_p,
///     since sum_p N_i g_p (x_p - x_i) = 0 by the definition of x_i;
///   - any linear phi field is left alone at every point, whatever the points' positions, the
///     conductances (k varies by orders of magnitude across a wetting front) and the edges of
///     the body: m_i = phi(x_i) (the weighted mean of a linear field), so every G_p and b_i is
///     grad phi. Only the curvature of phi and the jumps are acted on. (A plain weighted
///     node average, without the slope, is not: its weighted centre leaves the node where
///     g_p varies or points sit on one side, at an edge or with several points per element,
///     and a steady unsaturated flow then gains or loses liquid at O(h grad phi): on the V3
///     column 11 % of the p_L range instead of 0.7 %.) The slope comes from the neighbouring
///     centres, not from the node's own points: a plane fitted to a node's own points passes
///     through them where the node has three or fewer (at the edges) and would hide the jumps
///     there;
///   - the checkerboard is the largest jump field: inside a structured mesh every node's fan
///     holds as many up as down triangles, so the centres all hold the mean, G_p = 0 and
///     each point is drawn to the mean; it decays with the rate g_p/storage_p;
///   - the cap share storage_p / dt keeps the exchange stable in the explicit step (a point
///     moves at most `share` of the way to its node planes per step). In the saturated zone
///     the cap is what acts (storage is tiny); in the unsaturated zone alpha k/g0 does, and
///     there it adds a conductance of order alpha k to the curvature of phi only.
/// alpha is the material's `Locking Mitigation/Liquid Head Stabilisation` (0: off, the thesis).
/// The change enters the point mass balance as an extra flux divergence (PointRates), so the
/// outflow limit and the pressure update see it like any other flux.

#include "argine/core/Types.hpp"
#include "argine/physics/PointValueAveraging.hpp"

namespace argine {

class ActiveNodes;
class MaterialTable;
class NodalExchange;
struct MaterialPoints;
struct PointRates;
struct PointShapes;

class LiquidHeadStabilisation {
 public:
  LiquidHeadStabilisation() = default;
  /// Scratch for a mesh of `nodes` nodes, allocated only when a material of `table` asks for
  /// the stabilisation. On several MPI ranks, `exchange` completes the nodal sums.
  LiquidHeadStabilisation(const MaterialTable& table, int nodes, NodalExchange* exchange = nullptr);

  bool active() const { return active_; }

  /// Adds the exchange of the step (file comment) to the flux divergences of `rates`
  /// (complete mass balance) or to the relative divergences (simplified). `gravity` is the
  /// stage's (m/s^2, acting in -y).
  void apply(const MaterialTable& table, const MaterialPoints& points, const PointShapes& shapes,
             const ActiveNodes& active, PointRates& rates, Real dt, Real gravity);

  /// Reproducible sums (transfer/CompensatedSum.hpp): the node sums compensated.
  void compensateSums(bool on) {
    centres_.compensate(on);
    slopes_.compensate(on);
  }

 private:
  bool active_ = false;
  NodalExchange* exchange_ = nullptr;
  /// Nodal, weight g_p (kg/(Pa s); 0: not exchanged), mode kAverageNodal or kAverageNone:
  /// the node centres (phi, x, y; channel 0 then takes the node planes at the point) and
  /// the node slopes (the gradients through the centres of each point's nodes).
  AveragingScratch centres_, slopes_;
};

}  // namespace argine
