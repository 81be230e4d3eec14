#include "argine/slopestability/PointSection.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace argine {

namespace {

Real medianSpacing(const SectionPoints& points) {
  std::vector<Real> spacing(points.size());
  for (std::size_t p = 0; p < points.size(); ++p)
    spacing[p] = std::sqrt(std::max(points.volume[p], Real(0)));
  const auto middle = spacing.begin() + static_cast<std::ptrdiff_t>(spacing.size() / 2);
  std::nth_element(spacing.begin(), middle, spacing.end());
  return *middle;
}

}  // namespace

PointRaster::PointRaster(const SectionPoints& points, Real cell_size) {
  const std::size_t n = points.size();
  if (n == 0) throw std::invalid_argument("PointRaster: no points");
  if (points.y.size() != n || points.volume.size() != n || points.weight.size() != n ||
      points.pore_pressure.size() != n || points.saturation.size() != n ||
      points.material.size() != n)
    throw std::invalid_argument("PointRaster: the point arrays differ in length");
  cell_ = cell_size > 0 ? cell_size : 2 * medianSpacing(points);
  if (!(cell_ > 0)) throw std::invalid_argument("PointRaster: the points have no volume");
  Real x_min = points.x[0], x_max = x_min, y_min = points.y[0], y_max = y_min;
  for (std::size_t p = 0; p < n; ++p) {
    x_min = std::min(x_min, points.x[p]);
    x_max = std::max(x_max, points.x[p]);
    y_min = std::min(y_min, points.y[p]);
    y_max = std::max(y_max, points.y[p]);
  }
  // A margin cell, and the first points a quarter cell inside theirs: on a lattice of spacing
  // cell / 2 each cell then holds a 2 x 2 block whose centroid is the cell centre, so the
  // bilinear interpolation between cell means reproduces a linear field exactly.
  x0_ = x_min - 1.25 * cell_;
  y0_ = y_min - 1.25 * cell_;
  nx_ = static_cast<int>(std::floor((x_max - x0_) / cell_)) + 2;
  ny_ = static_cast<int>(std::floor((y_max - y0_) / cell_)) + 2;
  cells_.assign(static_cast<std::size_t>(nx_) * static_cast<std::size_t>(ny_), Cell{});

  int materials = 0;
  for (const int m : points.material) materials = std::max(materials, m + 1);
  std::vector<Real> material_volume(cells_.size() * static_cast<std::size_t>(materials), 0.0);
  std::vector<int> top_point(static_cast<std::size_t>(nx_), -1);  // highest top per column
  bottom_ = y_max;
  for (std::size_t p = 0; p < n; ++p) {
    const int i = column(points.x[p]), j = row(points.y[p]);
    const std::size_t c = static_cast<std::size_t>(j * nx_ + i);
    const Real v = points.volume[p];
    Cell& cell = cells_[c];
    cell.volume += v;
    cell.weight += points.weight[p];
    cell.pressure_volume += points.pore_pressure[p] * v;
    const Real dx = points.x[p] - (x0_ + (i + 0.5) * cell_);
    const Real dy = points.y[p] - (y0_ + (j + 0.5) * cell_);
    cell.sx += v * dx;
    cell.sy += v * dy;
    cell.sxx += v * dx * dx;
    cell.sxy += v * dx * dy;
    cell.syy += v * dy * dy;
    cell.spx += v * points.pore_pressure[p] * dx;
    cell.spy += v * points.pore_pressure[p] * dy;
    cell.saturation_volume += points.saturation[p] * v;
    material_volume[c * static_cast<std::size_t>(materials) +
                    static_cast<std::size_t>(points.material[p])] += v;
    const Real half = 0.5 * std::sqrt(std::max(v, Real(0)));
    bottom_ = std::min(bottom_, points.y[p] - half);
    int& top = top_point[static_cast<std::size_t>(i)];
    if (top < 0 ||
        points.y[p] + half > points.y[static_cast<std::size_t>(top)] +
                                 0.5 * std::sqrt(points.volume[static_cast<std::size_t>(top)]))
      top = static_cast<int>(p);
  }
  for (Cell& c : cells_) {
    if (!(c.volume > 0)) continue;
    // Weighted least squares for (a, b, c): the 3 x 3 normal equations by Cramer's rule.
    const Real m[3][3] = {{c.volume, c.sx, c.sy}, {c.sx, c.sxx, c.sxy}, {c.sy, c.sxy, c.syy}};
    const Real r[3] = {c.pressure_volume, c.spx, c.spy};
    const auto det3 = [](const Real a[3][3]) {
      return a[0][0] * (a[1][1] * a[2][2] - a[1][2] * a[2][1]) -
             a[0][1] * (a[1][0] * a[2][2] - a[1][2] * a[2][0]) +
             a[0][2] * (a[1][0] * a[2][1] - a[1][1] * a[2][0]);
    };
    const Real det = det3(m);
    // Degenerate (fewer than three points or all in a line): relative to V (d^2 V)^2.
    const Real scale = c.volume * std::pow(cell_ * cell_ * c.volume, 2);
    if (!(std::abs(det) > 1e-10 * scale)) {
      c.plane_a = c.pressure_volume / c.volume;
      continue;
    }
    Real solution[3];
    for (int k = 0; k < 3; ++k) {
      Real mk[3][3];
      for (int row = 0; row < 3; ++row)
        for (int col = 0; col < 3; ++col) mk[row][col] = col == k ? r[row] : m[row][col];
      solution[k] = det3(mk) / det;
    }
    c.plane_a = solution[0];
    c.plane_b = solution[1];
    c.plane_c = solution[2];
  }
  for (std::size_t c = 0; c < cells_.size(); ++c) {
    const Real* volumes = &material_volume[c * static_cast<std::size_t>(materials)];
    if (!(cells_[c].volume > 0)) continue;
    cells_[c].material = static_cast<int>(std::max_element(volumes, volumes + materials) - volumes);
  }

  // The envelope through each column's highest top, closed at the outermost points' sides.
  std::vector<Real> gx, gy;
  for (int i = 0; i < nx_; ++i) {
    const int p = top_point[static_cast<std::size_t>(i)];
    if (p < 0) continue;
    const std::size_t q = static_cast<std::size_t>(p);
    gx.push_back(points.x[q]);
    gy.push_back(points.y[q] + 0.5 * std::sqrt(std::max(points.volume[q], Real(0))));
  }
  const auto [left, right] = std::minmax_element(points.x.begin(), points.x.end());
  const auto halfOf = [&](std::vector<Real>::const_iterator at) {
    return 0.5 * std::sqrt(std::max(points.volume[static_cast<std::size_t>(at - points.x.begin())],
                                    Real(0)));
  };
  if (*left - halfOf(left) < gx.front()) {
    gx.insert(gx.begin(), *left - halfOf(left));
    gy.insert(gy.begin(), gy.front());
  }
  if (*right + halfOf(right) > gx.back()) {
    gx.push_back(*right + halfOf(right));
    gy.push_back(gy.back());
  }
  ground_ = Polyline(gx, gy);
}

int PointRaster::column(Real x) const {
  return std::clamp(static_cast<int>(std::floor((x - x0_) / cell_)), 0, nx_ - 1);
}

int PointRaster::row(Real y) const {
  return std::clamp(static_cast<int>(std::floor((y - y0_) / cell_)), 0, ny_ - 1);
}

int PointRaster::filledRow(int i, int j) const {
  for (int d = 0; d < ny_; ++d) {
    if (j - d >= 0 && cell(i, j - d).volume > 0) return j - d;
    if (j + d < ny_ && cell(i, j + d).volume > 0) return j + d;
  }
  return -1;
}

Real PointRaster::columnWeightDensity(Real x, Real y_bottom, Real y_top) const {
  if (!(y_top > y_bottom)) return 0;
  const int i = column(x);
  Real integral = 0;
  for (int j = row(y_bottom); j <= row(y_top); ++j) {
    const Real lower = std::max(y_bottom, y0_ + j * cell_);
    const Real upper = std::min(y_top, y0_ + (j + 1) * cell_);
    if (!(upper > lower)) continue;
    const int filled = filledRow(i, j);
    if (filled < 0) return 0;
    const Cell& c = cell(i, filled);
    integral += c.weight / c.volume * (upper - lower);
  }
  return integral;
}

Real PointRaster::interpolate(Real x, Real y, Real Cell::*numerator) const {
  // Bilinear weights on the four cell centres around (x, y), over those with points.
  const Real u = (x - x0_) / cell_ - 0.5, v = (y - y0_) / cell_ - 0.5;
  const int i0 = static_cast<int>(std::floor(u)), j0 = static_cast<int>(std::floor(v));
  const Real fu = u - i0, fv = v - j0;
  Real sum = 0, weights = 0;
  for (int di = 0; di <= 1; ++di)
    for (int dj = 0; dj <= 1; ++dj) {
      const int i = i0 + di, j = j0 + dj;
      if (i < 0 || j < 0 || i >= nx_ || j >= ny_) continue;
      const Cell& c = cell(i, j);
      if (!(c.volume > 0)) continue;
      const Real w = (di ? fu : 1 - fu) * (dj ? fv : 1 - fv);
      sum += w * (c.*numerator) / c.volume;
      weights += w;
    }
  if (weights > 1e-12) return sum / weights;
  const int i = column(x), filled = filledRow(i, row(y));
  return filled < 0 ? 0 : cell(i, filled).*numerator / cell(i, filled).volume;
}

Real PointRaster::planePressure(int i, int j, Real x, Real y) const {
  const Cell& c = cell(i, j);
  return c.plane_a + c.plane_b * (x - (x0_ + (i + 0.5) * cell_)) +
         c.plane_c * (y - (y0_ + (j + 0.5) * cell_));
}

Real PointRaster::porePressure(Real x, Real y) const {
  // An empty column (the raster's margin beyond the outermost points, where a slip circle
  // may leave the ground at a toe, or a gap in a broken mass) takes the plane of the nearest
  // column with points: without it, water standing at such an exit loses its pressure and
  // the mass its end thrust (a submerged 6 m slope: F 0.19 instead of about 0.5).
  const int i0 = column(x), j = row(y);
  for (int d = 0; d < nx_; ++d)
    for (const int i : {i0 - d, i0 + d}) {
      if (i < 0 || i >= nx_) continue;
      const int filled = filledRow(i, j);
      if (filled >= 0) return planePressure(i, filled, x, y);
    }
  return 0;
}

Real PointRaster::saturation(Real x, Real y) const {
  return interpolate(x, y, &Cell::saturation_volume);
}

Real PointRaster::surfaceWaterPressure(Real x, Real ground_y) const {
  return std::max(porePressure(x, ground_y), Real(0));
}

int PointRaster::material(Real x, Real y) const {
  const int i = column(x), filled = filledRow(i, row(y));
  return filled < 0 ? -1 : cell(i, filled).material;
}

SlopeSection sectionFromPoints(const SectionPoints& points, MaterialStrength strength,
                               Real cell_size, const Polyline* ground, Real water_unit_weight) {
  const auto raster = std::make_shared<const PointRaster>(points, cell_size);
  SlopeSection section;
  section.ground = ground ? *ground : raster->ground();
  section.floor = raster->bottom();
  section.layers.push_back(SoilLayer{"points", section.ground, 0, 0, 0});
  section.column_weight_field = [raster](Real x, Real y_bottom, Real y_top) {
    return raster->columnWeightDensity(x, y_bottom, y_top);
  };
  section.pore_pressure_field = [raster](Real x, Real y) { return raster->porePressure(x, y); };
  section.water_unit_weight = water_unit_weight;
  section.ponded_pressure_field = [raster, surface = section.ground](Real x) {
    return raster->surfaceWaterPressure(x, surface.at(x));
  };
  section.strength_field = [raster, strength](Real x, Real y, Real u) {
    const int material = raster->material(x, y);
    if (material < 0) return BaseStrength{};
    BaseStrength s = strength(material, u, raster->saturation(x, y));
    s.layer = material;
    return s;
  };
  return section;
}

}  // namespace argine
