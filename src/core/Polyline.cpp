#include "argine/core/Polyline.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "argine/core/Error.hpp"

namespace argine {

Polyline::Polyline(std::vector<Real> xs, std::vector<Real> ys)
    : x(std::move(xs)), y(std::move(ys)) {
  if (x.size() != y.size() || x.empty())
    throw std::invalid_argument("Polyline: as many x as y, at least one point");
  for (std::size_t i = 1; i < x.size(); ++i)
    if (!(x[i] > x[i - 1])) throw std::invalid_argument("Polyline: x must increase strictly");
}

Polyline::Polyline(const std::vector<std::array<Real, 2>>& vertices, const std::string& where) {
  if (vertices.empty()) throw InputError(where, "expected at least one (x, y) vertex");
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    if (i > 0 && !(vertices[i][0] > vertices[i - 1][0]))
      throw InputError(where, "x must increase from vertex to vertex; vertex " +
                                  std::to_string(i + 1) +
                                  " has x = " + std::to_string(vertices[i][0]) +
                                  " after x = " + std::to_string(vertices[i - 1][0]));
    x.push_back(vertices[i][0]);
    y.push_back(vertices[i][1]);
  }
}

Real Polyline::at(Real xq) const {
  if (x.empty()) return 0;
  if (xq <= x.front()) return y.front();
  if (xq >= x.back()) return y.back();
  // First point with x_i > xq; the segment is [i-1, i].
  const auto upper = std::upper_bound(x.begin(), x.end(), xq);
  const std::size_t i = static_cast<std::size_t>(upper - x.begin());
  const Real t = (xq - x[i - 1]) / (x[i] - x[i - 1]);
  return y[i - 1] + t * (y[i] - y[i - 1]);
}

}  // namespace argine
