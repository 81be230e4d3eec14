#pragma once
/// @file Types.hpp
/// Basic scalar types, the compile-time spatial dimension and the Kokkos spaces argine uses.

#include <Kokkos_Core.hpp>

namespace argine {

/// Floating point type of every physical quantity (SI units: Pa, m, s, kg).
using Real = double;

/// Spatial dimension, a compile-time constant so that small vectors have fixed size.
/// 2 = plane strain. 3D (tet4/hex8) is planned; code that depends on it uses kDim.
inline constexpr int kDim = 2;

/// Number of stored stress/strain components in plane strain: xx, yy, zz, xy.
inline constexpr int kStressComponents = 4;

/// Number of stored components of a velocity gradient or affine velocity matrix C (the
/// full kDim x kDim tensor, row-major: xx, xy, yx, yy).
inline constexpr int kAffineComponents = kDim * kDim;

/// Execution and memory spaces of the particle-grid kernels. Debian's Kokkos has only
/// Serial; kernels are written so OpenMP/CUDA work unchanged.
using ExecSpace = Kokkos::DefaultExecutionSpace;
using MemSpace = ExecSpace::memory_space;

/// Standard gravitational acceleration (m/s^2), the default of decks that switch gravity on.
inline constexpr Real kStandardGravity = 9.81;

}  // namespace argine
