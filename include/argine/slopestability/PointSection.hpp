#pragma once
/// @file PointSection.hpp
/// A limit-equilibrium section built from the material points of a run (P13 item 1): the
/// ground is the upper envelope of the points, unit weights and pore pressures come from the
/// points, the strength from each point's material at its suction. The points are binned on a
/// raster of square cells (a few points per cell); per cell the weight density is
/// sum(W_p) / sum(V_p) (the weight of the solid and the liquid a point carries over its
/// current volume), p_L and S_L are volume-weighted means, and the material is the one of the
/// largest volume. Host-side: evaluated at output times, not per step.

#include <functional>
#include <memory>
#include <vector>

#include "argine/core/Types.hpp"
#include "argine/slopestability/SlopeSection.hpp"

namespace argine {

/// What the section needs of each point, in plain host arrays of equal length.
struct SectionPoints {
  std::vector<Real> x, y;           ///< position (m)
  std::vector<Real> volume;         ///< current volume V_p (m^3 per m)
  std::vector<Real> weight;         ///< (M_S + M_L) g (N per m)
  std::vector<Real> pore_pressure;  ///< p_L (Pa, compression positive)
  std::vector<Real> saturation;     ///< S_L (-)
  std::vector<int> material;        ///< material index >= 0

  std::size_t size() const { return x.size(); }
};

/// The strength of material `material` at liquid pressure p_L and saturation S_L (suction
/// s = max(-p_L, 0) with the gas at zero pressure): supplied by the caller, which knows the
/// materials' models.
using MaterialStrength = std::function<BaseStrength(int material, Real p_L, Real S_L)>;

/// The raster the section samples (exposed for tests and for the slice table's neighbours).
class PointRaster {
 public:
  /// Bins `points` on square cells of `cell_size` (m); cell_size <= 0 takes twice the
  /// median point spacing sqrt(V_p), so that a cell holds about four points.
  PointRaster(const SectionPoints& points, Real cell_size);

  Real cellSize() const { return cell_; }
  /// The upper envelope of the points: per raster column, the highest point's top
  /// (y_p + sqrt(V_p) / 2) at that point's x; x increasing (m).
  const Polyline& ground() const { return ground_; }
  /// The lowest point's bottom (y_p - sqrt(V_p) / 2) (m).
  Real bottom() const { return bottom_; }

  /// Integral of the weight density over [y_bottom, y_top] of the column at x (N/m^2):
  /// cell by cell (piecewise constant); a cell without points below the envelope takes its
  /// column's nearest cell with points.
  Real columnWeightDensity(Real x, Real y_bottom, Real y_top) const;
  /// p_L at (x, y) (Pa): the volume-weighted least-squares plane of the p_L of the points
  /// in the cell at (x, y), or in its column's nearest cell with points (a column without
  /// points: the nearest column with points, its plane evaluated at (x, y)); a cell whose points
  /// do not span a plane (fewer than three, or in a line) takes their mean. Exact for a
  /// linear p_L (hydrostatic, steady uniform seepage) up to the surface, where the
  /// effective stress of a shallow slip surface is a small difference of large pressures.
  Real porePressure(Real x, Real y) const;
  /// S_L at (x, y) (-), as porePressure().
  Real saturation(Real x, Real y) const;
  /// The pressure of water standing on the ground at x (Pa, >= 0): porePressure() at the
  /// ground's height there (`ground_y`; the envelope's by default), so that under a water
  /// level the weight of the standing water and the pore pressures below come from the same
  /// planes; 0 where it is not positive (a dry or unsaturated surface).
  Real surfaceWaterPressure(Real x, Real ground_y) const;
  Real surfaceWaterPressure(Real x) const { return surfaceWaterPressure(x, ground_.at(x)); }
  /// The material of the largest volume in the cell at (x, y) or, if it is empty, in the
  /// nearest cell with points of its column; -1 if the column is empty.
  int material(Real x, Real y) const;

 private:
  struct Cell {
    Real volume = 0, weight = 0, pressure_volume = 0, saturation_volume = 0;
    /// p_L plane about the cell centre, p = a + b (x - x_c) + c (y - y_c), from the moments
    /// sum V (1, dx, dy) (1, dx, dy)^T and sum V p (1, dx, dy) (finished in the constructor).
    Real sxx = 0, sxy = 0, syy = 0, sx = 0, sy = 0, spx = 0, spy = 0;
    Real plane_a = 0, plane_b = 0, plane_c = 0;
    int material = -1;  ///< of the largest volume
  };
  int column(Real x) const;
  int row(Real y) const;
  const Cell& cell(int i, int j) const { return cells_[static_cast<std::size_t>(j * nx_ + i)]; }
  /// The cell with points nearest to row j in column i (-1: none).
  int filledRow(int i, int j) const;
  Real interpolate(Real x, Real y, Real Cell::*numerator) const;

  Real cell_ = 0, x0_ = 0, y0_ = 0, bottom_ = 0;
  int nx_ = 0, ny_ = 0;
  std::vector<Cell> cells_;
  Real planePressure(int i, int j, Real x, Real y) const;
  Polyline ground_;
};

/// The section of `points`: ground from the raster's envelope (or `ground` if given, e.g. the
/// deck's surface), floor at the lowest point, column weights and pore pressures from the
/// raster, strength from `strength` at each base's material, p_L and S_L, water standing on
/// the ground from the surface points' p_L (surfaceWaterPressure with water_unit_weight) at
/// the section's ground: a given ground above the envelope takes the soil's weight up to it
/// from the raster, so the standing water starts there too, not at the envelope.
SlopeSection sectionFromPoints(const SectionPoints& points, MaterialStrength strength,
                               Real cell_size = 0, const Polyline* ground = nullptr,
                               Real water_unit_weight = 9810);

}  // namespace argine
