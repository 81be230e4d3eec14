#pragma once
/// @file LiquidOutflowLimit.hpp
/// Donor limit of the liquid mass balance at dry points (V5 dry tail, doc/stability.md).
///
/// The complete mass balance (4.12, 4.16) moves M_L^{k+1} = M_L^k - V dt div(c w) with c and w
/// interpolated from the nodes, i.e. from the content of the NEIGHBOURS as well: a point near
/// residual saturation next to wetter ones can be asked to give away more liquid than it has
/// (measured: 0.0051 kg/m asked of 0.0026 kg/m at 15 MPa suction), M_L < 0, and no p_L
/// stores a negative mass. The residual water n S_min rho_L V is immobile (it is what the
/// retention curve never gives up, S_L -> S_min as s -> infinity); only the mobile content
///   M_mob = M_L - n S_min rho_L V
/// can leave a point, so one step's net outflow V dt div(c w) is capped at M_mob (a donor
/// limit, the upwind bound of a donor-cell scheme). The liquid the donor did not have was
/// never received either: it is withdrawn from the points that gained liquid in this step in
/// the donor's nodal support, in proportion to their gain (through the nodes with the shape
/// functions; any rest, where no neighbour gained, from all gaining points), so the total
/// liquid mass of the step is unchanged up to round-off. When no point exceeds its mobile
/// content the limit does nothing (wet runs are bit for bit unchanged).

#include <mpi.h>

#include "argine/core/Types.hpp"

namespace argine {

class MaterialTable;
class NodalExchange;
struct MaterialPoints;
struct PointRates;
struct PointShapes;

/// The part of a step's net outflow `outflow` (kg, > 0 leaving) that exceeds the mobile
/// content `mass - residual_mass` (kg) of the donor point: 0 when the point has the liquid.
KOKKOS_INLINE_FUNCTION Real excessOutflow(Real outflow, Real mass, Real residual_mass) {
  const Real mobile = mass > residual_mass ? mass - residual_mass : Real(0);
  return outflow > mobile ? outflow - mobile : Real(0);
}

/// What one application of the limit did (for the diagnostics and the tests).
struct OutflowLimitTotals {
  int limited_points = 0;  ///< points whose outflow was capped
  Real excess = 0;         ///< sum of the capped excess (kg per m)
  Real withdrawn = 0;      ///< sum withdrawn from the gaining points (kg per m), = excess
};

/// Applies the donor limit to rates.content_flux_divergence_increment_p (dt div(c w)) of the
/// liquid-carrying points with the complete mass balance, before updatePointStates. The
/// points' volume, porosity, M_L and rho_L must still be those of t^k. Nodal scratch is kept
/// between calls.
///
/// Several ranks (distribute): whether any point is limited is decided over all ranks (one
/// reduction per step), the nodal deficits and gains are completed at the shared nodes, and
/// the sums of step 4 are global, so a donor next to a rank border takes its liquid back from
/// the gaining points on both sides, as on one rank. The totals are then global.
class LiquidOutflowLimit {
 public:
  OutflowLimitTotals apply(const MaterialTable& table, const MaterialPoints& points,
                           const PointShapes& shapes, PointRates& rates);
  /// Several ranks: `exchange` completes node sums, `comm` reduces, `nodes` is the mesh's
  /// node count (every rank keeps arrays of all nodes). Null exchange: one rank.
  void distribute(NodalExchange* exchange, MPI_Comm comm, int nodes) {
    exchange_ = exchange;
    comm_ = comm;
    nodes_ = nodes;
  }

 private:
  /// Sums `values` over the ranks (nothing on one rank).
  void sumOverRanks(Real* values, int count) const;

  NodalExchange* exchange_ = nullptr;
  MPI_Comm comm_ = MPI_COMM_NULL;
  int nodes_ = 0;
  Kokkos::View<Real*, MemSpace> deficit_i_;  ///< sum N excess of the donors (kg)
  Kokkos::View<Real*, MemSpace> gain_i_;     ///< sum N gain of the gaining points (kg)
};

}  // namespace argine
