#pragma once
/// @file MaterialTable.hpp
/// The deck's materials as a Kokkos View of plain structs indexed by the point's material id,
/// so kernels read parameters by index (never by name, never through a virtual call).

#include <vector>

#include "argine/core/Types.hpp"
#include "argine/materials/MaterialParameters.hpp"
#include "argine/materials/SolidModel.hpp"

namespace argine {

struct MaterialSpec;

/// What a kernel needs to know about a point's material.
struct PointMaterial {
  PhaseModel phase = PhaseModel::Saturated;                  ///< dry, saturated or unsaturated
  MassBalanceForm mass_balance = MassBalanceForm::Complete;  ///< Eq. 4.12 or 4.14
  TensionCracks tension_cracks = TensionCracks::PoreSpace;   ///< unsaturated: keepsOpeningOut
  Real solid_density = 2650;                                 ///< rho_S (kg/m^3)
  SolidSpec solid;                                           ///< skeleton model
  SolidConstants solid_constants;  ///< solidConstants(solid), once per material
  LiquidSpec liquid;               ///< rho_L0, K_L, mu_L
  RetentionSpec retention;         ///< SWRC (unsaturated only)
  ConductivitySpec conductivity;   ///< HCC (k_sat filled)
  Real constrained_modulus = 0;    ///< E_c = constrainedModulus(solid) (Pa), once per material
  LockingMitigationSpec locking;   ///< anti-locking averaging (VolumetricAveraging.hpp)
};

/// Whether points of this phase model carry liquid (mass, pressure, velocity).
KOKKOS_INLINE_FUNCTION constexpr bool carriesLiquid(PhaseModel phase) {
  return phase != PhaseModel::Dry;
}

class MaterialTable {
 public:
  MaterialTable() = default;
  /// Copies `materials` (deck order = material id) to the device.
  explicit MaterialTable(const std::vector<MaterialSpec>& materials);

  /// Parameters by material id.
  Kokkos::View<const PointMaterial*, MemSpace> materials() const { return materials_m_; }
  /// 1 where the material carries liquid, by material id (the transfer kernels' flag).
  Kokkos::View<const int*, MemSpace> liquidCarrying() const { return liquid_m_; }
  /// Number of materials.
  int count() const { return static_cast<int>(materials_m_.extent(0)); }
  /// Host copy of one material's parameters.
  const PointMaterial& host(int material) const { return host_.at(material); }

 private:
  std::vector<PointMaterial> host_;
  Kokkos::View<PointMaterial*, MemSpace> materials_m_;
  Kokkos::View<int*, MemSpace> liquid_m_;
};

}  // namespace argine
