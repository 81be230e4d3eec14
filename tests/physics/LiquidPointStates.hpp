#pragma once
// Sets the liquid state of test points from a pressure field, consistently (the scenes of the
// point-liquid exchange tests: HeadScene.hpp, IntraElementSeepageTest.cpp).

#include "../transfer/TestScenes.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"

namespace argine::test {

/// p_L of each point from `pressure(q, x, y)`; rho_L (4.13), S_L and k (SWRC, HCC), the
/// porosity `porosity` and M_L = n S_L rho_L V consistent with it.
template <class PressureField>
void setLiquidStates(MaterialPoints& points, const PointMaterial& material, Real porosity,
                     PressureField&& pressure) {
  auto x = hostCopy(points.position);
  auto volume = hostCopy(points.volume);
  auto p = hostCopy(points.pressure_liquid);
  auto rho = hostCopy(points.density_liquid);
  auto s = hostCopy(points.saturation);
  auto k = hostCopy(points.conductivity);
  auto n = hostCopy(points.porosity);
  auto m = hostCopy(points.mass_liquid);
  for (int q = 0; q < points.count; ++q) {
    p(q) = pressure(q, x(q, 0), x(q, 1));
    const LiquidState state = saturationAndConductivity(material, p(q));
    rho(q) = liquidDensity(material.liquid, p(q));
    s(q) = state.saturation;
    k(q) = state.conductivity;
    n(q) = porosity;
    m(q) = porosity * s(q) * rho(q) * volume(q);
  }
  Kokkos::deep_copy(points.pressure_liquid, p);
  Kokkos::deep_copy(points.density_liquid, rho);
  Kokkos::deep_copy(points.saturation, s);
  Kokkos::deep_copy(points.conductivity, k);
  Kokkos::deep_copy(points.porosity, n);
  Kokkos::deep_copy(points.mass_liquid, m);
}

}  // namespace argine::test
