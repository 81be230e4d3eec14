#pragma once
/// @file SlopeSection.hpp
/// The cross-section a limit-equilibrium analysis works on (P13): the ground surface, soil
/// layers and the pore pressure, all as plain polylines in the (x, y) plane, y up, SI units
/// (m, N/m^3, Pa, rad). Host-side data: a slope analysis evaluates a few thousand trial
/// surfaces, not a per-point kernel, so std::vector and std::function are used freely.

#include <functional>
#include <limits>
#include <string>
#include <vector>

#include "argine/core/Polyline.hpp"
#include "argine/core/Types.hpp"

namespace argine {

/// A soil layer: its top line and Mohr-Coulomb effective strength. The layer fills the space
/// from its top down to the top of the next layer of the section (the last layer: down to
/// the bottom of the section).
struct SoilLayer {
  std::string name;
  Polyline top;             ///< top of the layer (m); ignored for the first layer (ground)
  Real unit_weight = 0;     ///< gamma (N/m^3), total unit weight
  Real cohesion = 0;        ///< c' (Pa)
  Real friction_angle = 0;  ///< phi' (rad)
};

/// The strength on a slip surface at one place: the material (layer) there, its effective
/// c' and phi', and the shear strength matric suction adds there, taken as an apparent
/// cohesion on the base (Pa; e.g. chi s tan(phi), Vanapalli et al. 1996, thesis Eq. 5.1).
struct BaseStrength {
  int layer = 0;
  Real cohesion = 0;          ///< c' (Pa)
  Real friction_angle = 0;    ///< phi' (rad)
  Real suction_strength = 0;  ///< (Pa), >= 0
};

/// A vertical load on the ground surface, varying linearly from q_start at x_start to q_end
/// at x_end (Pa, downwards positive), e.g. a surcharge strip.
struct SurfaceLoad {
  Real x_start = 0, x_end = 0;
  Real q_start = 0, q_end = 0;
};

/// The section: ground surface, layers from the top down, pore pressure, surface loads.
/// Layer tops may touch (a layer pinching out) but must not cross.
struct SlopeSection {
  Polyline ground;                ///< ground surface y(x) (m); slip surfaces must stay inside it
  std::vector<SoilLayer> layers;  ///< from the top down; at least one
  Real water_unit_weight = 9810;  ///< gamma_w (N/m^3)
  Polyline phreatic;              ///< phreatic line h_w(x) (m); empty: dry
  /// Pore pressure u(x, y) (Pa) given directly, e.g. interpolated from material points later;
  /// when set it replaces the phreatic line.
  std::function<Real(Real, Real)> pore_pressure_field;
  /// Weight per unit area of the vertical column at x between y_bottom and y_top (N/m^2),
  /// e.g. integrated from the material points' densities; when set it replaces the layers'
  /// unit weights in columnWeight().
  std::function<Real(Real, Real, Real)> column_weight_field;
  /// Strength at (x, y) where the pore pressure is u (Pa); when set it replaces the layers'
  /// c' and phi' in strengthAt() (e.g. the materials of the points with their suction).
  std::function<BaseStrength(Real, Real, Real)> strength_field;
  /// Lowest elevation a slip surface may reach (m), e.g. a rigid base; -inf: no limit.
  Real floor = -std::numeric_limits<Real>::infinity();
  /// Pressure of water standing on the ground at x (Pa, >= 0), e.g. from the material
  /// points at the surface; when set it replaces the phreatic line's ponding.
  std::function<Real(Real)> ponded_pressure_field;
  /// Vertical surface loads; a slice carries the load on its top as part of its weight
  /// (a vertical force on the slice's vertical line acts like weight in every method).
  std::vector<SurfaceLoad> loads;

  /// Index of the layer at (x, y): the deepest layer whose top lies at or above y (the first
  /// layer when y is above every top).
  int layerAt(Real x, Real y) const;

  /// Pore pressure (Pa) at (x, y): pore_pressure_field if set, otherwise the hydrostatic
  /// value below the phreatic line, u = gamma_w max(h_w(x) - y, 0), otherwise 0.
  Real porePressure(Real x, Real y) const;

  /// Strength at (x, y) with pore pressure u: strength_field if set, otherwise the c' and
  /// phi' of layerAt(x, y) and no suction strength.
  BaseStrength strengthAt(Real x, Real y, Real u) const;

  /// Weight per unit length of a vertical column of width `width` (m) at x between
  /// y_bottom and y_top (N/m): width times the sum over the layers of gamma times the
  /// thickness of the layer inside [y_bottom, y_top].
  Real columnWeight(Real x, Real y_bottom, Real y_top, Real width) const;

  /// Pressure of the water standing on the ground at x (Pa): ponded_pressure_field if set,
  /// otherwise gamma_w max(h_w(x) - y_ground(x), 0) where the phreatic line lies above the
  /// ground (a submerged slope), otherwise 0.
  Real pondedPressure(Real x) const;

  /// Resultant of the surface loads between x0 < x1 (N/m): the exact integral of q.
  Real surfaceLoad(Real x0, Real x1) const;
};

}  // namespace argine
