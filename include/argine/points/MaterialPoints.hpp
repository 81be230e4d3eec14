#pragma once
/// @file MaterialPoints.hpp
/// Material points as a structure of arrays of Kokkos Views ("_p" fields in kernels).
///
/// Sign conventions (stated once, see doc/theory.md): stresses and strains are positive
/// in tension; liquid pressure p_L is positive in compression (water pressure below the
/// water table is positive); suction s = -p_L where p_L < 0 (gas pressure is zero).
///
/// A new field must also be added to ARGINE_MATERIAL_POINT_FIELDS (points/PointFields.hpp),
/// which sorting, migration and checkpoints go through (a static_assert there checks it), and
/// kCheckpointFormatVersion incremented (doc/checkpoints.md).

#include <string>

#include "argine/core/Types.hpp"

namespace argine {

/// Stress/strain component order in the 4-vectors below (plane strain).
enum StressComponent { XX = 0, YY = 1, ZZ = 2, XY = 3 };

struct MaterialPoints {
  template <class T>
  using View = Kokkos::View<T, MemSpace>;

  int count = 0;  ///< number of points

  // Identity and location
  View<int*> id;                        ///< permanent point id (creation index), survives sorting
  View<int*> element;                   ///< index of the containing background element
  View<Real* [kDim]> local;             ///< local (reference-element) coordinates in that element
  View<Real* [kDim]> position;          ///< current position x (m)
  View<Real* [kDim]> initial_position;  ///< position at creation / last displacement reset (m)
  View<int*> material;                  ///< material index (into the deck's material list)

  // Kinematics
  View<Real* [kDim]> displacement;     ///< solid displacement u = x - x0 (m)
  View<Real* [kDim]> velocity_solid;   ///< v_S (m/s)
  View<Real* [kDim]> velocity_liquid;  ///< v_L (m/s)
  /// APIC's affine velocity matrices C (Jiang et al. 2015), components (xx, xy, yx, yy) with
  /// C_jk ~ d v_j / d x_k (1/s): a point carries v + C (x - x_p) around it. Zero and unread
  /// with the FLIP transfer (TransferScheme, transfer/TwoPhaseTransfer.hpp).
  View<Real* [kAffineComponents]> affine_velocity_solid;
  View<Real* [kAffineComponents]> affine_velocity_liquid;
  /// (P12) the displacement at the start of the current window of an explicit stage's `Hand
  /// Back At Rest` (m; simulation/RestMonitor.hpp); unread otherwise.
  View<Real* [kDim]> rest_reference;

  // Geometry and phase masses
  View<Real*> volume;          ///< current volume V (m^3 per metre thickness in 2D)
  View<Real*> initial_volume;  ///< V0 (m^3)
  View<Real*> mass_solid;      ///< M_S = (1-n) rho_S V, constant (kg)
  View<Real*> mass_liquid;     ///< M_L = n S_L rho_L V (kg)
  View<Real*> porosity;        ///< n (-)
  /// Volumetric strain of the point's openings from its neighbours, not yet closed again
  /// (>= 0; PointUpdates.hpp: separateFromNeighbours, closeSeparation): the gap a tensile
  /// return left, which compressive strain closes before it compresses the point.
  View<Real*> separation;

  // Liquid state
  View<Real*> pressure_liquid;  ///< p_L (Pa, compression positive)
  View<Real*> density_liquid;   ///< rho_L (kg/m^3), weakly compressible (4.13)
  View<Real*> saturation;       ///< S_L (-)
  View<Real*> conductivity;     ///< hydraulic conductivity k(S_L) (m/s)

  // Mechanics
  View<Real* [kStressComponents]> stress_effective;  ///< Bishop effective stress sigma' (Pa)
  View<Real* [kStressComponents]> strain;            ///< total small-strain accumulation (-)
  View<Real*> deviatoric_strain;                     ///< equivalent deviatoric strain (-)
  View<Real*> plastic_strain;                        ///< equivalent plastic strain (-)
  View<int*> plastic_state;  ///< 0 elastic, 1 plastic, 2 apex, 3 tension cut-off

  /// Allocate all fields for n points, zero-initialised.
  void allocate(int n);
};

}  // namespace argine
