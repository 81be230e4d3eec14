#pragma once
/// @file PolylineSlip.hpp
/// A non-circular slip surface: a polyline (x, y) with increasing x, e.g. following a weak
/// seam, cut into vertical slices by the same code as a circle (Slicing.hpp). The mass is
/// the part of the section above the polyline and below the ground, between the first point
/// where the polyline goes below the ground (entry) and the last where it comes back up
/// (exit).

#include "argine/core/Types.hpp"
#include "argine/slopestability/Slice.hpp"
#include "argine/slopestability/SlopeSection.hpp"

namespace argine {

/// Cuts the mass above `surface` into about `slice_count` slices of equal width between its
/// entry and exit, with the vertices of the surface, the ground and the layer tops added as
/// slice boundaries so that all of them are straight over every slice (the midpoint weight is
/// then exact). Per slice, alpha is the inclination of the polyline segment under it. The
/// ends of the polyline must lie on or above the ground (within 1e-9 of the mass's span):
/// the entry and exit are where it crosses the ground, found exactly on the piecewise linear
/// difference ground - surface. Rejected (valid = false): a polyline starting or ending below
/// the ground, never below it, crossing outside the ground line, or a base below
/// section.floor. split_at_materials: also cut where the surface crosses a layer top
/// (materialBoundaryCrossings, Slicing.hpp), so that no slice base straddles two materials.
SlipMass slicePolyline(const SlopeSection& section, const Polyline& surface, int slice_count,
                       bool split_at_materials = false);

}  // namespace argine
