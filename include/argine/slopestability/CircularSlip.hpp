#pragma once
/// @file CircularSlip.hpp
/// A circular slip surface cut into vertical slices (the method of slices, Fellenius 1936;
/// Bishop 1955): where the circle leaves and re-enters the ground, and per slice the base
/// midpoint, width b, base angle alpha, weight W, base pore pressure u and base material.

#include <vector>

#include "argine/core/Types.hpp"
#include "argine/slopestability/Slice.hpp"
#include "argine/slopestability/SlopeSection.hpp"

namespace argine {

/// A trial circle: centre (m) and radius (m).
struct SlipCircle {
  Real centre_x = 0;
  Real centre_y = 0;
  Real radius = 0;
};

/// Crossings of the lower half of `circle` with the ground polyline, sorted by x.
std::vector<Real> lowerArcGroundCrossings(const SlopeSection& section, const SlipCircle& circle);

/// Cuts the mass above `circle` into about `slice_count` slices of equal width between the
/// outermost crossings; the vertices of the ground line and of the layer tops inside the mass
/// are added as slice boundaries so that they are straight over every slice (sliceColumns,
/// Slicing.hpp). Weights are column weights at the slice midpoints (midpoint rule).
/// Rejected (valid = false): fewer than two crossings of the lower arc with the ground, a mass
/// running out of the ground line, a base below section.floor.
/// split_at_materials: also cut where the arc crosses a layer top (materialBoundaryCrossings,
/// Slicing.hpp), so that no slice base straddles two materials.
/// The moment of mass.end_forces about the circle's centre divided by R, in the sense of
/// sum W sin(alpha) (clockwise positive: a force towards +x below the centre counts
/// negative), the `external_driving` of Bishop.hpp:  -sum H (y_c - y_H) / R.
Real endForceDriving(const SlipMass& mass, const SlipCircle& circle);

SlipMass sliceCircle(const SlopeSection& section, const SlipCircle& circle, int slice_count,
                     bool split_at_materials = false);

}  // namespace argine
