#pragma once
/// @file MaterialParameters.hpp
/// Plain parameter structs of the constitutive, retention and conductivity models, in SI
/// units. They hold only numbers and enums, so kernels copy them by value.

#include "argine/core/Types.hpp"

namespace argine {

enum class PhaseModel { Dry, Saturated, Unsaturated };
enum class SolidModel { LinearElastic, MohrCoulomb, SuctionMohrCoulomb };
enum class RetentionModel { Linear, VanGenuchten, Gardner };
enum class ConductivityModel { Constant, Hillel, Mualem, Gardner };
enum class MassBalanceForm { Complete, Simplified };  ///< Eq. 4.12 or Eq. 4.14
/// What fills the opening of an unsaturated point at the tension cut-off
/// (physics/PointUpdates.hpp, keepsOpeningOut): its own pore space, on the soil's retention
/// curve (the thesis), or air, a crack open to the surface (with suction at the start of the
/// step; the opening is then kept out of the pores, as for a dry point, and the point drains
/// into the crack above p_L = 0 while it is open).
enum class TensionCracks { PoreSpace, AirFilled };
/// Anti-locking averaging of a point quantity's increment (physics/VolumetricAveraging.hpp):
/// none, over the points of the element (MPM-MIXED style), or through the nodes (nodal mixed
/// discretisation).
enum class IncrementAveraging { None, Element, Nodal };

struct SolidSpec {
  SolidModel model = SolidModel::LinearElastic;
  Real youngs_modulus = 0;     ///< E (Pa)
  Real poisson_ratio = 0;      ///< nu (-)
  Real cohesion = 0;           ///< c' (Pa)
  Real friction_angle = 0;     ///< phi' (rad; the deck gives degrees)
  Real dilatancy_angle = 0;    ///< psi (rad; the deck gives degrees)
  Real tensile_strength = 0;   ///< tension cut-off sigma_1 <= tensile_strength (Pa)
  bool tension_cutoff = true;  ///< whether the cut-off applies (MohrCoulomb.hpp)
  // Suction-dependent Mohr-Coulomb (4.23-4.26): c = c' + dc_max (1 - exp(-B s/p_atm)),
  // phi = phi' + A s / p_atm.
  Real cohesion_increase_max = 0;        ///< dc_max (Pa)
  Real cohesion_suction_rate = 0;        ///< B (-)
  Real friction_suction_rate = 0;        ///< A (rad)
  Real atmospheric_pressure = 101325.0;  ///< p_atm (Pa)
  /// F of a strength-reduction trial (P13; simulation/StrengthReductionSearch.hpp): c(s),
  /// tan phi(s) and the cut-off divided by it (mohrCoulombStrength). 1: the material as given.
  Real strength_reduction = 1;
};

/// Volumetric-locking / cell-crossing mitigation of a material.
struct LockingMitigationSpec {
  IncrementAveraging volumetric_strain = IncrementAveraging::None;  ///< d eps_vol of the solid
  IncrementAveraging liquid_pressure = IncrementAveraging::None;    ///< d p_L (saturated points)
  /// alpha of the liquid head stabilisation (physics/LiquidHeadStabilisation.hpp); 0: off
  Real head_stabilisation = 0;
  /// Darcy exchange between the points of one element (physics/IntraElementSeepage.hpp)
  bool intra_element_seepage = false;
  /// whose points exchange: one element's (Element) or those sharing a node (Nodal)
  IncrementAveraging seepage_patch = IncrementAveraging::Element;
  /// L (m): the `element` averages above are taken over square patches of side L that tile
  /// the mesh (physics/AveragingPatches.hpp), so that their length does not shrink with the
  /// cells; 0: one element each
  Real averaging_length = 0;
  /// the `element` averages of each step passed through the filter q <- q/2 + (sum of the
  /// edge neighbours' q)/(2 n), n the most edge neighbours a row has (4 on a grid of cells),
  /// which removes the averages' checkerboard mode (physics/PointValueAveraging.hpp)
  bool checkerboard_filter = false;
  /// the nodal forces take, instead of each point's own, the mean stress and liquid pressure
  /// averaged (and filtered) as the increments are: the work conjugates of the averaged
  /// d eps_vol and div v_L (B-bar; physics/VolumetricAveraging.hpp)
  bool conjugate_mean_stress = false;
};

struct LiquidSpec {
  Real density = 1000.0;      ///< rho_L at zero pressure (kg/m^3)
  Real bulk_modulus = 2.2e9;  ///< K_L (Pa), Eq. 4.13
  Real viscosity = 1.0e-3;    ///< mu_L (Pa s)
};

struct RetentionSpec {
  RetentionModel model = RetentionModel::Linear;
  Real linear_slope = 0;        ///< a_v (1/Pa), Eq. 5.6: S_L = S_max - a_v s
  Real reference_pressure = 0;  ///< p_ref (Pa), van Genuchten Eq. 4.28
  Real lambda = 0.5;            ///< lambda (-), van Genuchten Eq. 4.28
  Real gardner_alpha = 0;       ///< alpha (1/Pa), Gardner exponential
  Real saturation_min = 0;      ///< S_min (-)
  Real saturation_max = 1;      ///< S_max (-)
  /// p_a (Pa): absolute pressure of the air occluded in the pores at p_L = 0. With p_a > 0
  /// the 1 - S_max of air left at p_L >= 0 compresses by Boyle's law (occludedAirSaturation);
  /// 0: it does not, S_L = S_max at every p_L >= 0 (the thesis).
  Real occluded_air_pressure = 0;
};

struct ConductivitySpec {
  ConductivityModel model = ConductivityModel::Constant;
  Real intrinsic_permeability = 0;  ///< kappa (m^2); the deck gives this or k_sat
  Real saturated_conductivity = 0;  ///< k_sat = kappa rho_L g / mu_L (m/s), g = 9.81
  Real hillel_exponent = 3;         ///< r (-), Eq. 4.30
  Real mualem_lambda = 0.5;         ///< lambda* (-), Eq. 4.31
  Real gardner_alpha = 0;           ///< alpha (1/Pa)
  /// Hillel (4.30) and Mualem (4.31) use S_L as the thesis writes them (false) or the
  /// effective saturation S_e = (S_L - S_min)/(S_max - S_min) of the usual Mualem-van
  /// Genuchten form (true).
  bool use_effective_saturation = false;
};

}  // namespace argine
