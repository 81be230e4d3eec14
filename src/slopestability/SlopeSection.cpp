#include "argine/slopestability/SlopeSection.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

namespace argine {

Polyline::Polyline(std::vector<Real> xs, std::vector<Real> ys)
    : x(std::move(xs)), y(std::move(ys)) {
  if (x.size() != y.size() || x.empty()) {
    throw std::invalid_argument("Polyline: as many x as y, at least one point");
  }
  for (std::size_t i = 1; i < x.size(); ++i) {
    if (!(x[i] > x[i - 1])) throw std::invalid_argument("Polyline: x must increase strictly");
  }
}

Real Polyline::at(Real xq) const {
  if (xq <= x.front()) return y.front();
  if (xq >= x.back()) return y.back();
  const auto upper = std::upper_bound(x.begin(), x.end(), xq);
  const std::size_t i = static_cast<std::size_t>(upper - x.begin());
  const Real t = (xq - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

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

Real SlopeSection::columnWeight(Real xq, Real y_bottom, Real y_top, Real width) const {
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
