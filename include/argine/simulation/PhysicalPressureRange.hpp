#pragma once
/// @file PhysicalPressureRange.hpp
/// The physical range of the liquid pressure p_L of the material points, and the count of
/// the points outside it (issue P11 item 2): written as a column of <name>_diagnostics.csv
/// and logged at every output where it is not zero.
///
/// Upper bound: the largest total vertical stress the model can carry in equilibrium,
///   sigma_v,max = g [rho_max (y_top - y_bottom) + rho_w max(h_w - y_top, 0)] + q_max,
/// rho_max the largest mixture density (M_S + M_L) / V of the points, y_top / y_bottom the
/// top and bottom of the points (centre +- half the side sqrt(V) of the point's square), h_w
/// the highest free water level of the stage's total heads (water standing above the soil
/// adds its weight) and q_max the largest surface pressure the stage applies (tractions,
/// prescribed liquid pressures). A pore pressure above it pushes the grains apart harder than
/// all the weight and loads of the model press them together: the effective stress of that
/// point is tensile beyond anything equilibrium can give it. Why the static overburden and
/// not the points' current total stress: a point with a spurious p_L carries that p_L in its
/// own total stress (sigma = sigma' - S_L p_L), so a bound taken from the current total
/// stresses would grow with the error it should detect. Dynamic overstress of a sliding
/// mass (an impact) is not in the bound; the levee slides are far from that (a 70 kPa bound
/// against p_L up to +302 kPa, issue P11).
///
/// Lower bound, per material: the most negative p_L that both the initial state with
/// drainage and the retention curve allow,
///   max( min(p_L,min,0, 0, -rho_L g H), -s_max ),
/// p_L,min,0 the most negative p_L of the material's points in the initial state (after the
/// Initialisation), H the height of the initial body (top to bottom of its points): without
/// evaporation, suction grows beyond the initial state's only by drainage, and drained to a
/// water table at the very bottom of the model the top carries rho_L g H of suction (a
/// drawdown lowers the water table, so the initial state alone is too tight); 0 (drainage to
/// the atmosphere) is always reachable. s_max is the suction at which the retention curve
/// reaches S_min (the linear curve: (S_max - S_min) / a_v): past it no liquid is left to
/// drain; van Genuchten and Gardner approach S_min only asymptotically and set no bound.
/// Dilation of an unsaturated body could in principle raise suction further; the levee soils
/// of the scenes have none (psi = 0).
/// Dry materials carry no p_L and are not checked; points outside the mesh (element < 0,
/// frozen) neither.

#include <limits>
#include <string>
#include <vector>

#include "argine/core/Types.hpp"
#include "argine/input/Deck.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

/// What a stage adds to the weight of the points in the upper bound.
struct StageSurcharge {
  Real water_level = -std::numeric_limits<Real>::infinity();  ///< highest h_w (m)
  Real water_density = 1000;                                  ///< rho_w of that head (kg/m^3)
  Real surface_pressure = 0;                                  ///< q_max (Pa)
};

/// The stage's surcharge: the highest value any total-head table or file of the stage reaches
/// (over the whole stage, not only now), the largest |traction| and prescribed liquid
/// pressure (constant or series), with the stage's gravity.
StageSurcharge stageSurcharge(const StageSpec& stage);

/// sigma_v,max (Pa) of the file comment for the located points, gravity `gravity` (m/s^2,
/// along -y). 0 without located points.
Real largestTotalVerticalStress(const MaterialPoints& points, Real gravity,
                                const StageSurcharge& surcharge);

/// The lower bound (Pa) of each material (deck order) from the initial points under gravity
/// `gravity` (m/s^2; file comment); -infinity for dry materials.
std::vector<Real> lowestPhysicalPressures(const MaterialPoints& initial,
                                          const std::vector<MaterialSpec>& materials, Real gravity);

/// The points outside [lowest(material), highest] and the worst of them: the one farthest
/// outside its range.
struct PressureRangeCount {
  int outside = 0;          ///< points with p_L above `highest` or below their material's lowest
  int above = 0;            ///< of which above `highest`
  Real highest = 0;         ///< the upper bound used (Pa)
  Real worst_pressure = 0;  ///< p_L of the worst point (Pa)
  Real worst_bound = 0;     ///< the bound it crosses (Pa)
  int worst_id = -1;        ///< its id
  Real worst_position[kDim] = {0, 0};  ///< its position (m)
};

/// Counts the located, liquid-carrying points of `points` outside their physical range.
PressureRangeCount countPressuresOutsideRange(const MaterialPoints& points,
                                              const std::vector<MaterialSpec>& materials,
                                              const std::vector<Real>& lowest, Real highest);

/// The log line of a count > 0: "<n> point(s) with p_L outside the physical range at t = <t>
/// s (<a> above sigma_v,max = <h> kPa, <b> below their material's lowest p_L); worst: point
/// <id> at (x, y) m, p_L = <p> kPa (bound <bound> kPa)".
std::string describePressureRange(const PressureRangeCount& count, Real time);

}  // namespace argine
