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
/// Liquid: q = d p_L of the step at saturated points, w = n V (pore volume); then rho_L from
/// (4.13) and M_L = n rho_L V. sum n V d p_L is kept, so the liquid mass is kept to first
/// order in d p_L / K_L.
///
/// Conjugate mean stress (`Conjugate Mean Stress`, element or nodal averaging of d eps_vol):
/// the strain a point is given, eps_p + (A a)_p - a_p with a the volumetric part and (A a)_p
/// its average (element, patch or nodal), does virtual work sum_p V_p s_p : d eps_p with the
/// in-plane mean stress m_p = (s_xx + s_yy) / 2 replaced by (A m)_p: the same average of m
/// with weight V (every one of these A is self-adjoint in the weights V: V_p A_pq symmetric). So
/// the nodal forces take the mixture's total mean stress m' - S_L p_L and the liquid's p_L (the
/// conjugate of the averaged div v_L) averaged as d eps_vol is: B-bar, a symmetric stiffness for
/// any tangent, where the point's own mean stress made the coupling of neighbouring cells one-sided
/// and a sliding body grew the cells' checkerboard (and, with the nodal average, dilatant plastic
/// flow ran away: doc/theory.md Sec. 3.3.4). Never with the checkerboard filter F (checkDeck): F
/// maps the checkerboard to zero, and forces from F A m would leave a checkerboard of m and
/// p_L without any force against it (a free mode; V1's p_L error x2.3, cell to cell).

#include "argine/core/Types.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/transfer/TransferScheme.hpp"

namespace argine {

class ActiveNodes;
class MaterialTable;
class NodalExchange;
struct MaterialPoints;
struct Mesh;
struct PointRates;
struct PointShapes;

class VolumetricAveraging {
 public:
  VolumetricAveraging() = default;
  /// Scratch for `mesh`, allocated only when a material of `table` asks for an averaging,
  /// with the patches of its `Averaging Length (m)` (AveragingPatches.hpp) if one gives it.
  /// On several MPI ranks, `exchange` completes the nodal sums at the nodes shared with other
  /// ranks and `comm` the sums of patches (an element, and so its own element sums, belongs
  /// to one rank only; a patch may not).
  VolumetricAveraging(const MaterialTable& table, const Mesh& mesh,
                      NodalExchange* exchange = nullptr, MPI_Comm comm = MPI_COMM_NULL);

  /// Whether any material averages the volumetric strain / the liquid pressure increment.
  bool averagesStrain() const { return strain_; }
  bool averagesPressure() const { return pressure_; }

  /// Replaces d eps_vol of the points whose material asks for it (file comment). `active`
  /// holds the nodes of the points' elements.
  void averageStrainIncrements(const MaterialTable& table, const MaterialPoints& points,
                               const PointShapes& shapes, const ActiveNodes& active,
                               PointRates& rates);
  /// Whether some material's forces take the conjugate mean stress.
  bool conjugatesMeanStress() const { return conjugate_; }
  /// Per point the shifts (x: of the mixture's total mean stress, y: of p_L in the liquid's
  /// force) that give the forces the element's (or patch's) averages instead of the point's own
  /// values (file comment); zero where the point's material does not ask for it. Fills
  /// meanStressShifts().
  void averageMeanStresses(const MaterialTable& table, const MaterialPoints& points,
                           const PointShapes& shapes, const ActiveNodes& active);
  MeanStressShifts meanStressShifts() const { return mean_shift_p_; }
  /// Keeps p_L of every point before the liquid mass balance of the step.
  void rememberPressures(const MaterialPoints& points);
  /// After the mass balance: averages d p_L = p_L - remembered p_L of the saturated points
  /// whose material asks for it; rho_L and M_L follow.
  void averagePressureIncrements(const MaterialTable& table, const MaterialPoints& points,
                                 const PointShapes& shapes, const ActiveNodes& active);

  /// Reproducible sums (transfer/CompensatedSum.hpp): the node and element sums compensated.
  void compensateSums(bool on) {
    increments_.compensate(on);
    pressure_increments_.compensate(on);
    mean_stresses_.compensate(on);
  }

 private:
  /// The channels of increments_: the three increments of the step averaged together (one
  /// exchange on several ranks).
  enum Channel : int { kFluxDivergence = 0, kRelativeDivergence, kVolumetricStrain, kChannels };
  /// The common case, every point's three channels nodal or none (the levee decks): the
  /// channels share one weight column, and the increments are read and the averages put back
  /// by the scatter and the gather themselves (no per-point scratch): the same sums and
  /// quotients as averagePointValues, so the same bits, with two passes over the points
  /// instead of four and four node columns instead of six.
  void averageNodalChannelsTogether(const MaterialPoints& points, const PointShapes& shapes,
                                    const ActiveNodes& active, PointRates& rates);
  bool strain_ = false;
  /// Every material's volumetric strain averaging nodal on a liquid-carrying phase, or none.
  bool all_nodal_ = false;
  /// all_nodal_: (node, c) sum N V q_c for the three channels, (node, kChannels) sum N V; after
  /// the division (node, c) holds channel c's average.
  Kokkos::View<Real * [kChannels + 1], MemSpace> nodal_sums_;
  Kokkos::View<int*, MemSpace> nodal_m_;  ///< all_nodal_: per material, 1 where it averages
  bool pressure_ = false;
  NodalExchange* exchange_ = nullptr;           ///< several ranks: completes the node sums
  AveragingScratch increments_;                 ///< the strain and liquid increments (Channel)
  AveragingScratch pressure_increments_;        ///< d p_L (one channel)
  Kokkos::View<Real*, MemSpace> old_pressure_;  ///< p_L before the step
  bool conjugate_ = false;
  /// The channels of mean_stresses_, in the order of MeanStressShifts' columns: the mixture's
  /// total in-plane mean stress and p_L.
  enum MeanChannel : int { kMixtureMean = 0, kLiquidPressure, kMeanChannels };
  static_assert(kMeanChannels == MeanStressShifts::static_extent(1));
  AveragingScratch mean_stresses_;  ///< the mixture's mean stress and p_L (MeanChannel)
  MeanStressShifts mean_shift_p_;   ///< averageMeanStresses' shifts
};

}  // namespace argine
