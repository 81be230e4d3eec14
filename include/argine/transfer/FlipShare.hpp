#pragma once
/// @file FlipShare.hpp
/// The FLIP share in APIC's point velocity update (VelocityBlend, TransferScheme.hpp): one
/// formula for the element families (TwoPhaseTransfer.cpp) and the grid families
/// (GridPointTransfers.hpp), on one point (Real) or kLanes points (Lanes).
#include "argine/core/Types.hpp"

namespace argine {

/// v_APIC + (1 - alpha) (v_FLIP - v_APIC): APIC's velocity `v_grid` with the share
/// 1 - `grid_share` of FLIP's v_p + dt sum N a_i (`v_flip`) in its place.
template <class T>
KOKKOS_INLINE_FUNCTION T withFlipShare(const T& v_grid, const T& v_flip, Real grid_share) {
  return v_grid + (1 - grid_share) * (v_flip - v_grid);
}

}  // namespace argine
