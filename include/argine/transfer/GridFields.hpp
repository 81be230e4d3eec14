#pragma once
/// @file GridFields.hpp
/// Nodal fields of one explicit two-phase step ("_i" fields in kernels). Nothing here is
/// state: every field is rebuilt from the material points each step (thesis Sec. 3.3, step
/// 8), and only the nodes of elements that hold points (ActiveNodes) are ever non-zero.
///
/// Liquid momentum equation (4.36) is written per unit LIQUID volume (intrinsic form, 4.1):
/// its lumped mass is M~_L = sum N rho_L V (4.38, 4.46) and its gravity load uses the same
/// mass (the thesis prints m_L in 4.41; rho_L V is what makes a hydrostatic column balance).
/// The mixture equation (4.37) uses M_S (4.40) and M_L = sum N n S_L rho_L V (4.39).

#include <string>
#include <vector>

#include "argine/core/Types.hpp"
#include "argine/transfer/CompensatedSum.hpp"

namespace argine {

class ActiveNodes;

struct GridFields {
  template <class T>
  using View = Kokkos::View<T, MemSpace>;

  // Lumped masses and coefficients (thesis 4.38-4.40, 4.45)
  View<Real*> mass_solid_i;             ///< M_S = sum N M_S,p (kg), 4.40
  View<Real*> mass_liquid_i;            ///< M_L = sum N n S_L rho_L V (kg), 4.39
  View<Real*> mass_liquid_intrinsic_i;  ///< M~_L = sum N rho_L V (kg), 4.38 with 4.46
  View<Real*> drag_i;                   ///< lumped Q_L = sum N n S_L rho_L g / k V (kg/s), 4.45
  View<Real*> volume_liquid_i;          ///< sum N V over liquid-carrying points (m^3)
  View<Real*> liquid_content_i;         ///< rho_L n S_L at the node (kg/m^3), for 4.16

  // Momenta, velocities and accelerations
  View<Real* [kDim]> momentum_solid_i;       ///< sum N M_S v_S (kg m/s)
  View<Real* [kDim]> momentum_liquid_i;      ///< sum N rho_L V v_L (kg m/s), intrinsic weights
  View<Real* [kDim]> velocity_solid_i;       ///< v_S (m/s)
  View<Real* [kDim]> velocity_liquid_i;      ///< v_L (m/s)
  View<Real* [kDim]> acceleration_solid_i;   ///< a_S (m/s^2)
  View<Real* [kDim]> acceleration_liquid_i;  ///< a_L (m/s^2)

  // Forces: external minus internal (the drag is applied in the nodal solve)
  View<Real* [kDim]> force_mixture_i;  ///< f^ext - f^int of the mixture (N), 4.42, 4.44
  View<Real* [kDim]> force_liquid_i;   ///< f_L^ext - f_L^int of the liquid (N), 4.41, 4.43

  /// Allocate every field for `num_nodes` nodes, zero-initialised.
  void allocate(int num_nodes);
  /// Number of nodes the fields were allocated for.
  int numNodes() const { return static_cast<int>(mass_solid_i.extent(0)); }

  /// Zero every field on the listed nodes only (the nodes the last step touched), so an
  /// empty part of the background mesh costs nothing per step.
  void zero(const ActiveNodes& nodes);
};

/// Reproducible sums (CompensatedSum.hpp): the P2G sums of mapPointsToGrid (masses, drag,
/// liquid volume, momenta, forces), complete over the ranks, folded with their low parts
/// `lo` at the listed nodes (lo = 0 after).
void foldCompensatedGridSums(const ActiveNodes& nodes, GridFields& grid,
                             const LowParts<GridFields>& lo);
/// The same for the momenta alone (the remap of updatePointVelocitiesAndMapMomenta).
void foldCompensatedMomenta(const ActiveNodes& nodes, GridFields& grid,
                            const LowParts<GridFields>& lo);

}  // namespace argine
