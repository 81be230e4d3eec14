#pragma once
/// @file PointRates.hpp
/// What the grid tells each material point at the end of a step (thesis Sec. 3.3, step 4):
/// its strain increment and the terms of the liquid mass balance (4.12, 4.15-4.16), all
/// interpolated from the updated nodal velocities. Scratch of one step, not point state.

#include "argine/core/Types.hpp"

namespace argine {

struct PointRates {
  template <class T>
  using View = Kokkos::View<T, MemSpace>;

  View<Real* [kStressComponents]>
      strain_increment_p;  ///< d eps = dt sym(grad v_S); xx, yy, zz, xy (tensor shear)
  View<Real*> liquid_divergence_increment_p;  ///< dt div v_L (-)
  /// dt div(c w) = dt (c div w + grad c . w) with c = rho_L n S_L and w = v_L - v_S both
  /// interpolated from the nodes (kg/m^3): the liquid flux of 4.11-4.12 with the
  /// advective-gradient term of 4.15-4.16.
  View<Real*> content_flux_divergence_increment_p;
  View<Real* [kDim]> displacement_increment_p;  ///< dt v_S at the point (m), 7.13
  /// Spin increment w = dt (dv_S,x/dy - dv_S,y/dx) / 2 (rad) of the solid: the Jaumann
  /// rotation of the stress (materials/ObjectiveStressRate.hpp).
  View<Real*> spin_increment_p;

  /// Allocate for n points.
  void allocate(int n);
  /// Number of points allocated for.
  int count() const { return static_cast<int>(liquid_divergence_increment_p.extent(0)); }
};

}  // namespace argine
