#pragma once
/// @file K0Procedure.hpp
/// The K0 procedure of thesis Ch. 4 Sec. 5.1 (Figs. 4.6-4.7): initial liquid pressure,
/// saturation and effective stress of every material point from a ground surface, a
/// phreatic surface (which may lie above the ground: an outside water level, e.g. a river)
/// and each material's K0. Formulas in K0Formulas.hpp; theory in doc/theory.md
/// ("Initialisation").
///
/// At a point (x, y) of material m:
///   p_L      = rho_L g (y_ph(x) - y), capped at -s_max above the phreatic surface; without a
///              phreatic surface, the material's uniform Initial State p_L
///   S_L, k   = the material's SWRC/HCC at p_L (saturated: 1, k_sat; dry: no liquid)
///   sigma_yy = -( int_y^{y_g(x)} gamma(x, z) dz + rho_L g max(0, y_ph(x) - y_g(x)) ),
///              gamma = (1 - n) rho_S g + n S_L(p_L(z)) rho_L g of the material actually at
///              (x, z) in the mesh (dry layers (1 - n) rho_S g, empty elements 0; in a
///              rectangle with Regions, the region polygons, VerticalColumns.hpp); a point
///              above the ground line carries only the free water above it, if any
///   sigma'_yy = sigma_yy + S_L p_L (Bishop, chi = S_L), sigma'_xx = sigma'_zz = K0 sigma'_yy
/// and rho_L = rho_L0 exp(p_L/K_L) (4.13), M_L = n S_L rho_L V (4.47).
/// The hydrostatic profile uses rho_L0 (the compressibility changes it by p_L/K_L < 1e-4).

#include <string>
#include <vector>

#include "argine/core/Polyline.hpp"
#include "argine/core/Types.hpp"
#include "argine/init/VerticalColumns.hpp"
#include "argine/physics/MaterialTable.hpp"

namespace argine {

struct InitialisationSpec;
struct MaterialPoints;
struct MaterialSpec;
struct Mesh;

/// The K0 state at one position.
struct K0State {
  Real liquid_pressure = 0;             ///< p_L (Pa)
  Real saturation = 0;                  ///< S_L (-), 0 for dry material
  Real total_vertical_stress = 0;       ///< sigma_yy (Pa, <= 0)
  Real effective_vertical_stress = 0;   ///< sigma'_yy (Pa)
  Real earth_pressure_coefficient = 1;  ///< K0
};

/// The K0 profiles of one deck over one mesh (host-side).
class K0Profile {
 public:
  /// `gravity` (m/s2) is the magnitude the stresses must balance (the first stage's).
  /// Throws InputError("Initialisation/...") for a bad polyline.
  K0Profile(const InitialisationSpec& spec, const Mesh& mesh,
            const std::vector<MaterialSpec>& materials, Real gravity);

  /// p_L of material m at (x, y) (Pa); 0 for a dry material.
  Real liquidPressure(int material, Real x, Real y) const;
  /// S_L of material m at p_L: 0 dry, 1 saturated, the SWRC unsaturated.
  Real saturation(int material, Real pressure) const;
  /// Unit weight of material m at (x, y) (N/m3).
  Real unitWeight(int material, Real x, Real y) const;
  /// sigma_yy at (x, y) (Pa): the overburden of the mesh's layers between y and the ground
  /// surface plus the free water above the ground.
  Real totalVerticalStress(Real x, Real y) const;
  /// Everything at a point of material m at (x, y).
  K0State state(int material, Real x, Real y) const;
  /// The materials as kernels read them.
  const MaterialTable& table() const { return table_; }

 private:
  /// int_a^b gamma_m(x, z) dz (N/m2) for a <= b.
  Real layerWeight(int material, Real x, Real a, Real b) const;

  std::vector<MaterialSpec> materials_;
  MaterialTable table_;
  Polyline ground_, phreatic_;
  Real max_suction_ = -1;
  Real gravity_ = 0;
  VerticalColumns columns_;
};

/// Sets p_L, rho_L, S_L, k, M_L and sigma' of every point by the K0 procedure (after
/// initialisePointState, which set masses, porosity and zeroed the kinematics).
void applyK0Procedure(const K0Profile& profile, MaterialPoints& points);

/// Sets p_L = pressure[p] and with it rho_L (4.13), S_L and k (SWRC, HCC) and M_L = n S_L
/// rho_L V (4.47) of every liquid-carrying point (dry points are left alone): the liquid
/// state of the K0 procedure and of the pore-pressure initialisation (P10).
void setPointLiquidPressures(const MaterialTable& table, const std::vector<Real>& pressure,
                             MaterialPoints& points);

/// The pore-pressure initialisation (deck `Initialisation/Method: pore pressure`, P10): p_L
/// of every point from the table (y, p_L) or hydrostatic from the phreatic surface, rho_L0 g
/// (y_ph(x) - y), capped at the maximum suction, as the K0 procedure's p_L; the stress stays
/// each material's Initial State. Returns a description for the log.
std::string applyPorePressure(const InitialisationSpec& spec,
                              const std::vector<MaterialSpec>& materials, Real gravity,
                              MaterialPoints& points);

}  // namespace argine
