#pragma once
/// @file StabilityCases.hpp
/// The cases of the critical time-step study V5 (thesis Ch. 4 Sec. 7.3, VERIFICATION.md V5):
/// one column set-up per soil (van Genuchten sets of Table 4.6), porosity, Young's modulus,
/// intrinsic permeability, column scale and degree of saturation, and the critical steps
/// every implemented criterion predicts for it.

#include <string>
#include <vector>

#include "argine/core/Types.hpp"
#include "argine/input/Deck.hpp"
#include "argine/timestep/Criteria.hpp"

namespace argine::stability {

/// A van Genuchten set of Table 4.6 (S_max = 1).
struct SoilSet {
  const char* name;
  Real reference_pressure;  ///< p_ref (Pa)
  Real lambda;              ///< (-)
  Real saturation_min;      ///< S_min (-)
};

/// Table 4.6: sand, silt, clay.
inline constexpr SoilSet kSoils[] = {
    {"sand", 9.9e3, 0.8, 0.003}, {"silt", 100.0e3, 0.75, 0.001}, {"clay", 196.0e3, 0.5, 0.001}};

/// One column of the study.
struct StabilityCase {
  std::string family = "saturation";  ///< saturation | permeability | mesh | realistic
  int soil = 1;                       ///< index into kSoils
  Real porosity = 0.4;                ///< n (-)
  Real youngs_modulus = 1.0e7;        ///< E (Pa)
  Real permeability = 2.0e-10;        ///< intrinsic permeability kappa (m^2), constant
  Real liquid_bulk_modulus = 8.0e7;   ///< K_L (Pa)
  Real saturation = 1;                ///< target S_L of the uniform initial suction (-)
  Real scale = 1;                     ///< 1: 1 m x 0.05 m column, elements 0.05 m; 10: 10x
};

/// The degrees of saturation of the study: S_L = 1 to 0.01 (8 levels).
std::vector<Real> saturationLevels();

/// The cases of a named set:
///  saturation   3 soils x n {0.4, 0.6} x E {1e4, 5e4} kPa x 8 S_L levels, kappa 2e-10 m2
///  permeability silt, kappa {1e-9, 8e-11, 7e-12} m2 (2e-10 is in "saturation"), n {0.4,
///               0.6}, E 1e4 kPa, same S_L levels
///  mesh         silt, the column scaled 10x (elements 0.5 m), same n, E, S_L
///  all          the three above
///  core         "saturation" at E 1e4 kPa only (24 fewer cases per modulus)
///  quick        6 cases: sand n 0.4 and clay n 0.6 at S_L 1 and 0.5 (kappa 2e-10 m2), silt
///               n 0.6, kappa 7e-12 m2 at S_L 0.5 and 0.3 (the unit test)
///  realistic    clay at k ~ 1e-9 m/s (kappa 1e-16 m2), elements 0.5 m, real K_L 2.2 GPa
/// std::invalid_argument for another name.
std::vector<StabilityCase> caseSet(const std::string& name);

/// The suction (Pa) at which the soil of `c` has S_L = c.saturation (0 for S_L = 1).
Real caseSuction(const StabilityCase& c);

/// `base` (the stability_column.yaml deck) made into case `c`, run with the fixed step `dt`:
/// soil, n, E, kappa, K_L, uniform initial and top suction, and the column scaled by c.scale
/// (height 1 m x scale, 20 square elements of 0.05 m x scale, one element wide).
Deck caseDeck(const Deck& base, const StabilityCase& c, Real dt);

/// The criteria's input at the initial state of a case deck (uniform: any point).
CriterionInput criterionInputOf(const Deck& deck);

/// Every criterion of kAllCriteria at that state (s), in enum order.
std::vector<Real> predictedSteps(const CriterionInput& in);

/// Mieremet's saturated criterion (4.67 at S_L = 1, dS_L/ds = 0) for the same soil (s).
Real saturatedMieremetStep(CriterionInput in);

/// The first guess of the search: the smaller of the coupled criterion and the adapted
/// Mieremet criterion, the two the thesis finds closest to the empirical step.
Real searchGuess(const CriterionInput& in);

/// "sand", "silt", "clay".
const char* soilName(const StabilityCase& c);

}  // namespace argine::stability
