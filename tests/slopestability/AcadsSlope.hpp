#pragma once
// ACADS slope-stability test problem 1(a) (AcadsBenchmarkTest.cpp gives the source): the
// section, the search grid the tests use on it, and points filling it on a lattice, shared by
// the tests that build on this slope.

#include <cmath>
#include <vector>

#include "argine/slopestability/CircleSearch.hpp"
#include "argine/slopestability/PointSection.hpp"

namespace argine::acads {

constexpr Real kDegree = M_PI / 180;
constexpr Real kUnitWeight = 20e3;          ///< gamma (N/m^3)
constexpr Real kCohesion = 3e3;             ///< c' (Pa)
constexpr Real kFriction = 19.6 * kDegree;  ///< phi' (rad)

/// Toe bench y = 25 from x = 20 to 30, a 2:1 face to (50, 35), crest to x = 70, floor y = 20.
inline Polyline problem1aGround() {
  return Polyline({20, 30, 50, 70}, {25, 25, 35, 35});
}

inline SlopeSection problem1a() {
  SlopeSection s;
  s.ground = problem1aGround();
  s.layers.push_back({"soil", s.ground, kUnitWeight, kCohesion, kFriction});
  s.floor = 20;
  return s;
}

/// Centres over the region above the slope, tangents from the floor to below the crest.
inline CircleSearchGrid problem1aGrid(int slices = 50) {
  CircleSearchGrid grid;
  grid.centre_x_min = 25;
  grid.centre_x_max = 55;
  grid.centre_y_min = 36;
  grid.centre_y_max = 66;
  grid.tangent_y_min = 20;
  grid.tangent_y_max = 34;
  grid.refinements = 3;
  grid.slice_count = slices;
  return grid;
}

/// Points on a lattice of spacing h (cell centres of an h-grid) below `ground`, above
/// y_bottom, between x_left and x_right; unit weight gamma, S_L = 1, material 0;
/// p_L = pressure(x, y).
template <class Pressure>
SectionPoints latticeBelow(const Polyline& ground, Real x_left, Real x_right, Real y_bottom, Real h,
                           Real gamma, Pressure pressure) {
  SectionPoints pts;
  for (Real x = x_left + h / 2; x < x_right; x += h)
    for (Real y = y_bottom + h / 2; y < ground.at(x); y += h) {
      pts.x.push_back(x);
      pts.y.push_back(y);
      pts.volume.push_back(h * h);
      pts.weight.push_back(gamma * h * h);
      pts.pore_pressure.push_back(pressure(x, y));
      pts.saturation.push_back(1);
      pts.material.push_back(0);
    }
  return pts;
}

}  // namespace argine::acads
