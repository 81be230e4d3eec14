#pragma once
/// @file CircularSlip.hpp
/// A circular slip surface cut into vertical slices (the method of slices, Fellenius 1936;
/// Bishop 1955): where the circle leaves and re-enters the ground, and per slice the base
/// midpoint, width b, base angle alpha, weight W, base pore pressure u and base material.

#include <string>
#include <vector>

#include "argine/core/Types.hpp"
#include "argine/slopestability/SlopeSection.hpp"

namespace argine {

/// A trial circle: centre (m) and radius (m).
struct SlipCircle {
  Real centre_x = 0;
  Real centre_y = 0;
  Real radius = 0;
};

/// One slice of the sliding mass. alpha is the inclination of the base at its midpoint,
/// sin(alpha) = (x_mid - centre_x) / R: positive where the base rises with x.
struct Slice {
  Real x_mid = 0;           ///< abscissa of the base midpoint (m)
  Real width = 0;           ///< b (m)
  Real base_y = 0;          ///< elevation of the base midpoint (m)
  Real top_y = 0;           ///< ground elevation above the base midpoint (m)
  Real base_angle = 0;      ///< alpha (rad)
  Real weight = 0;          ///< W (N per m run)
  Real pore_pressure = 0;   ///< u at the base midpoint (Pa)
  int layer = 0;            ///< index of the layer at the base midpoint
  Real cohesion = 0;        ///< c' of the base material (Pa)
  Real friction_angle = 0;  ///< phi' of the base material (rad)
  /// Shear strength matric suction adds on the base (Pa), an apparent cohesion; set by the
  /// section's strength (BaseStrength), 0 for a saturated or dry base.
  Real suction_strength = 0;

  /// Length of the base, b / cos(alpha) (m).
  Real baseLength() const;
};

/// The sliding mass of a circle, or why there is none.
struct SlipMass {
  bool valid = false;
  std::string reason;         ///< why the circle was rejected (empty when valid)
  Real entry_x = 0;           ///< leftmost crossing of the lower arc with the ground (m)
  Real exit_x = 0;            ///< rightmost crossing (m)
  std::vector<Slice> slices;  ///< from left to right
};

/// Crossings of the lower half of `circle` with the ground polyline, sorted by x.
std::vector<Real> lowerArcGroundCrossings(const SlopeSection& section, const SlipCircle& circle);

/// Cuts the mass above `circle` into about `slice_count` slices of equal width between the
/// outermost crossings; the vertices of the ground line inside the mass are added as slice
/// boundaries so that the ground is straight over every slice. Weights are column weights at
/// the slice midpoints (midpoint rule). Rejected (valid = false): fewer than two crossings of
/// the lower arc with the ground, a mass running out of the ground line, a base below
/// section.floor.
SlipMass sliceCircle(const SlopeSection& section, const SlipCircle& circle, int slice_count);

}  // namespace argine
