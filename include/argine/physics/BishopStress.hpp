#pragma once
/// @file BishopStress.hpp
/// Bishop's effective stress with chi = S_L (thesis Eq. 4.5): sigma = sigma' - S_L p_L I,
/// stresses tension positive, p_L compression positive. The one place of the pore-pressure
/// term chi p_L that the P2G's forces, the conjugate mean stress and the K0 procedure read.

#include <Kokkos_Core.hpp>

namespace argine {

/// chi p_L = S_L p_L (Pa), for one point (Real) or a pack of lanes (Lanes).
template <class T>
KOKKOS_INLINE_FUNCTION T bishopPorePressure(T saturation, T pressure) {
  return saturation * pressure;
}

}  // namespace argine
