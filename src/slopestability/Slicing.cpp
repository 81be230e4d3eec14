#include "argine/slopestability/Slicing.hpp"

#include <algorithm>
#include <cmath>

namespace argine {

Real Slice::baseLength() const {
  return width / std::cos(base_angle);
}

std::vector<Real> sliceBoundaries(Real entry_x, Real exit_x, int slice_count,
                                  const std::vector<Real>& extra) {
  std::vector<Real> bounds;
  const Real span = exit_x - entry_x;
  for (int i = 0; i <= slice_count; ++i) bounds.push_back(entry_x + span * i / slice_count);
  for (const Real xv : extra) {
    if (xv > entry_x && xv < exit_x) bounds.push_back(xv);
  }
  std::sort(bounds.begin(), bounds.end());
  bounds.erase(std::unique(bounds.begin(), bounds.end(),
                           [span](Real p, Real q) { return std::abs(p - q) <= 1e-9 * span; }),
               bounds.end());
  return bounds;
}

std::vector<Real> sectionVertices(const SlopeSection& section) {
  std::vector<Real> xs = section.ground.x;
  for (std::size_t i = 1; i < section.layers.size(); ++i) {
    const std::vector<Real>& top = section.layers[i].top.x;
    xs.insert(xs.end(), top.begin(), top.end());
  }
  if (!section.phreatic.empty() && !section.ponded_pressure_field) {  // ponding linear per slice
    xs.insert(xs.end(), section.phreatic.x.begin(), section.phreatic.x.end());
  }
  for (const SurfaceLoad& load : section.loads) {
    xs.push_back(load.x_start);
    xs.push_back(load.x_end);
  }
  return xs;
}

std::vector<Real> materialBoundaryCrossings(const SlopeSection& section,
                                            const std::vector<Real>& bounds, const SlipBase& base) {
  std::vector<Real> crossings;
  for (std::size_t k = 1; k < section.layers.size(); ++k) {
    const Polyline& top = section.layers[k].top;
    const auto gap = [&](Real x) { return top.at(x) - base.elevation(x); };
    for (std::size_t i = 1; i < bounds.size(); ++i) {
      Real a = bounds[i - 1], b = bounds[i];
      Real ga = gap(a);
      const Real gb = gap(b);
      if (ga == 0 || gb == 0 || (ga < 0) == (gb < 0)) continue;
      for (int it = 0; it < 60; ++it) {
        const Real m = 0.5 * (a + b);
        const Real gm = gap(m);
        if ((gm < 0) == (ga < 0)) {
          a = m;
          ga = gm;
        } else {
          b = m;
        }
      }
      crossings.push_back(0.5 * (a + b));
    }
  }
  return crossings;
}

std::vector<HorizontalForce> pondedWaterEndForces(const SlopeSection& section, Real entry_x,
                                                  Real exit_x) {
  // Water of depth d = p / gamma_w standing against a vertical end of the mass pushes on it
  // with gamma_w d^2 / 2 at d / 3 above the ground there: towards +x at the entry (left) end,
  // towards -x at the exit end. With the water's weight on the slices this is the whole
  // force and moment of the water on the mass (the water above the mass is in equilibrium).
  std::vector<HorizontalForce> forces;
  const Real gamma = section.water_unit_weight;
  for (const auto& [x, towards] : {std::pair<Real, Real>{entry_x, 1}, {exit_x, -1}}) {
    const Real p = section.pondedPressure(x);
    if (!(p > 0) || !(gamma > 0)) continue;
    const Real depth = p / gamma;
    forces.push_back({towards * 0.5 * p * depth, section.ground.at(x) + depth / 3, x});
  }
  return forces;
}

std::vector<Slice> sliceColumns(const SlopeSection& section, const std::vector<Real>& bounds,
                                const SlipBase& base) {
  std::vector<Slice> slices;
  for (std::size_t i = 1; i < bounds.size(); ++i) {
    Slice s;
    s.width = bounds[i] - bounds[i - 1];
    s.x_mid = 0.5 * (bounds[i] + bounds[i - 1]);
    s.base_y = base.elevation(s.x_mid);
    s.top_y = section.ground.at(s.x_mid);
    s.base_angle = base.inclination(s.x_mid);
    s.weight = s.top_y > s.base_y ? section.columnWeight(s.x_mid, s.base_y, s.top_y, s.width) : 0;
    s.weight += section.surfaceLoad(bounds[i - 1], bounds[i]);
    s.weight += section.pondedPressure(s.x_mid) * s.width;  // water standing on the slice
    s.pore_pressure = section.porePressure(s.x_mid, s.base_y);
    const BaseStrength strength = section.strengthAt(s.x_mid, s.base_y, s.pore_pressure);
    s.layer = strength.layer;
    s.cohesion = strength.cohesion;
    s.friction_angle = strength.friction_angle;
    s.suction_strength = strength.suction_strength;
    slices.push_back(s);
  }
  return slices;
}

void sliceMass(const SlopeSection& section, const SlipBase& base, int slice_count,
               bool split_at_materials, const std::vector<Real>& surface_vertices, SlipMass& mass) {
  // Slice boundaries: equal widths, plus the ground's, layer tops' and the surface's vertices
  // inside the mass (and, on request, where the base crosses a layer top).
  std::vector<Real> extra = sectionVertices(section);
  extra.insert(extra.end(), surface_vertices.begin(), surface_vertices.end());
  std::vector<Real> bounds = sliceBoundaries(mass.entry_x, mass.exit_x, slice_count, extra);
  if (split_at_materials) {
    const std::vector<Real> crossings = materialBoundaryCrossings(section, bounds, base);
    extra.insert(extra.end(), crossings.begin(), crossings.end());
    bounds = sliceBoundaries(mass.entry_x, mass.exit_x, slice_count, extra);
  }
  mass.slices = sliceColumns(section, bounds, base);
  mass.end_forces = pondedWaterEndForces(section, mass.entry_x, mass.exit_x);
  mass.valid = true;
}

}  // namespace argine
