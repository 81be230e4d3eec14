#include "argine/slopestability/SlopeSection.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace argine {

int SlopeSection::layerAt(Real xq, Real yq) const {
  int found = 0;
  for (std::size_t i = 1; i < layers.size(); ++i) {
    if (layers[i].top.at(xq) >= yq) found = static_cast<int>(i);
  }
  return found;
}

Real SlopeSection::porePressure(Real xq, Real yq) const {
  if (pore_pressure_field) return pore_pressure_field(xq, yq);
  if (phreatic.empty()) return 0;
  return water_unit_weight * std::max(phreatic.at(xq) - yq, Real(0));
}

BaseStrength SlopeSection::strengthAt(Real xq, Real yq, Real u) const {
  if (strength_field) return strength_field(xq, yq, u);
  BaseStrength strength;
  strength.layer = layerAt(xq, yq);
  const SoilLayer& layer = layers[static_cast<std::size_t>(strength.layer)];
  strength.cohesion = layer.cohesion;
  strength.friction_angle = layer.friction_angle;
  return strength;
}

Real SlopeSection::pondedPressure(Real xq) const {
  if (ponded_pressure_field) return std::max(ponded_pressure_field(xq), Real(0));
  if (phreatic.empty()) return 0;
  return water_unit_weight * std::max(phreatic.at(xq) - ground.at(xq), Real(0));
}

Real SlopeSection::columnWeight(Real xq, Real y_bottom, Real y_top, Real width) const {
  if (column_weight_field) return width * column_weight_field(xq, y_bottom, y_top);
  Real weight_per_width = 0;
  for (std::size_t i = 0; i < layers.size(); ++i) {
    // Layer i spans from the top of layer i+1 up to its own top (the first layer up to the
    // ground, the last down to the bottom of the section).
    const Real upper = i == 0 ? y_top : std::min(layers[i].top.at(xq), y_top);
    const Real lower =
        i + 1 < layers.size() ? std::max(layers[i + 1].top.at(xq), y_bottom) : y_bottom;
    weight_per_width += layers[i].unit_weight * std::max(upper - lower, Real(0));
  }
  return width * weight_per_width;
}

Real SlopeSection::surfaceLoad(Real x0, Real x1) const {
  Real total = 0;
  for (const SurfaceLoad& load : loads) {
    const Real a = std::max(x0, load.x_start), b = std::min(x1, load.x_end);
    if (!(b > a) || !(load.x_end > load.x_start)) continue;
    // q linear on the overlap: its mean is q at the overlap's midpoint.
    const Real t = (0.5 * (a + b) - load.x_start) / (load.x_end - load.x_start);
    total += (b - a) * (load.q_start + t * (load.q_end - load.q_start));
  }
  return total;
}

}  // namespace argine
