#pragma once
/// @file Slicing.hpp
/// The slicing both kinds of trial surface share: between an entry and an exit abscissa,
/// slices of equal width plus extra boundaries (ground vertices, layer-top vertices, the
/// vertices of a polyline surface), and per slice the base midpoint, alpha, W, u and the base
/// material. A circle and a polyline differ only in the base elevation and inclination they
/// hand in.

#include <functional>
#include <vector>

#include "argine/core/Types.hpp"
#include "argine/slopestability/Slice.hpp"
#include "argine/slopestability/SlopeSection.hpp"

namespace argine {

/// The slip surface as the slicer sees it: elevation y(x) (m) and inclination alpha(x) (rad,
/// positive where it rises with x) at an abscissa inside the mass.
struct SlipBase {
  std::function<Real(Real)> elevation;
  std::function<Real(Real)> inclination;
};

/// Slice boundaries between entry_x and exit_x: slice_count equal widths, plus every value of
/// `extra` strictly inside, sorted, with near-duplicates (closer than 1e-9 of the span)
/// merged.
std::vector<Real> sliceBoundaries(Real entry_x, Real exit_x, int slice_count,
                                  const std::vector<Real>& extra);

/// Abscissae of the ground's and the layer tops' vertices and of the ends of the surface
/// loads: boundaries that keep the ground, every layer top and every load linear over each
/// slice, so the midpoint weight is exact and a load acts (nearly) on the slice's midline.
std::vector<Real> sectionVertices(const SlopeSection& section);

/// Where the base crosses a layer top between consecutive boundaries (a sign change of
/// top - base at the two ends, located by bisection): extra boundaries that keep every slice
/// base in one material. Without them a slice straddling a material boundary takes the
/// material of its midpoint for the whole base, and a search can pick out surfaces where that
/// error is favourable.
std::vector<Real> materialBoundaryCrossings(const SlopeSection& section,
                                            const std::vector<Real>& bounds, const SlipBase& base);

/// The thrusts of water standing against the ends of a mass between entry_x and exit_x
/// (SlopeSection::pondedPressure there): gamma_w d^2 / 2 towards the mass, d / 3 above the
/// ground.
std::vector<HorizontalForce> pondedWaterEndForces(const SlopeSection& section, Real entry_x,
                                                  Real exit_x);

/// One slice per pair of consecutive boundaries: base midpoint from `base`, weight as the
/// column weight at the midpoint times the width (midpoint rule) plus the surface load on the
/// slice's top and the water standing on it (pondedPressure at the midpoint times the
/// width), u and material at the base midpoint. suction_strength is left 0.
std::vector<Slice> sliceColumns(const SlopeSection& section, const std::vector<Real>& bounds,
                                const SlipBase& base);

/// Slices `mass` (entry_x and exit_x set) over `base`: boundaries of sliceBoundaries with the
/// section's vertices and `surface_vertices` (a polyline surface's), cut at layer tops when
/// split_at_materials, the slices of sliceColumns and the water's end thrusts; valid = true.
void sliceMass(const SlopeSection& section, const SlipBase& base, int slice_count,
               bool split_at_materials, const std::vector<Real>& surface_vertices, SlipMass& mass);

}  // namespace argine
