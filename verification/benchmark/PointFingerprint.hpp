#pragma once
/// @file PointFingerprint.hpp
/// Hashes of the whole point state that tell whether two runs gave bit-for-bit the same
/// results, whatever order the points are stored in (FNV-1a over the bit patterns of every
/// point field, PointFields.hpp).

#include "argine/points/MaterialPoints.hpp"

namespace argine::benchmark {

/// One hash of all fields, the points taken in id order (ids 0 .. count - 1).
unsigned long long fingerprint(const MaterialPoints& points);

/// The sum (mod 2^64) over the points of each point's own hash of all its fields: additive,
/// so the sum of the ranks' values is the fingerprint of the distributed state, equal to the
/// one of a single rank holding the same points with the same values.
unsigned long long additiveFingerprint(const MaterialPoints& points);

}  // namespace argine::benchmark
