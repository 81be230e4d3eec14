#pragma once
/// @file Slice.hpp
/// One vertical slice of a sliding mass (the method of slices, Fellenius 1936; Bishop 1955)
/// and the sliced mass of a trial surface, circular or not. Every factor-of-safety method
/// works on a vector of slices only, so circles and polylines share them.

#include <string>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

/// One slice of the sliding mass. alpha is the inclination of the base at its midpoint,
/// positive where the base rises with x (for a circle sin(alpha) = (x_mid - centre_x) / R).
/// Weight and forces are per metre run of the section.
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
  /// Shear strength added by matric suction (Pa), set by the caller (e.g. from an
  /// unsaturated strength such as Vanapalli et al. 1996 or Fredlund et al. 1978,
  /// S = (u_a - u_w) tan(phi_b)). Every method adds it to c' as an apparent cohesion on the
  /// base, (c' + S) l; the slicers leave it 0.
  Real suction_strength = 0;

  /// Length of the base, b / cos(alpha) (m).
  Real baseLength() const;
  /// c' + suction_strength (Pa): the cohesion every method uses.
  Real apparentCohesion() const { return cohesion + suction_strength; }
};

/// A horizontal force on the sliding mass (N per m run, positive towards +x) and the
/// elevation of its line of action (m): the thrust of water standing against an end of the
/// mass (PondedWater.hpp).
struct HorizontalForce {
  Real force = 0;
  Real y = 0;
  Real x = 0;  ///< the end of the mass it acts on (m): it loads the slice there
};

/// The sliding mass of a trial surface, or why there is none.
struct SlipMass {
  bool valid = false;
  std::string reason;         ///< why the surface was rejected (empty when valid)
  Real entry_x = 0;           ///< leftmost point where the surface meets the ground (m)
  Real exit_x = 0;            ///< rightmost point (m)
  std::vector<Slice> slices;  ///< from left to right
  /// Horizontal forces on the ends of the mass (water standing against them); the weight of
  /// water standing on the mass is part of the slices' weights.
  std::vector<HorizontalForce> end_forces;
};

}  // namespace argine
