#include "argine/init/Polyline.hpp"

#include <algorithm>

#include "argine/core/Error.hpp"

namespace argine {

Polyline::Polyline(std::vector<std::array<Real, 2>> vertices, const std::string& where)
    : vertices_(std::move(vertices)) {
  if (vertices_.empty()) throw InputError(where, "expected at least one (x, y) vertex");
  for (std::size_t i = 1; i < vertices_.size(); ++i)
    if (!(vertices_[i][0] > vertices_[i - 1][0]))
      throw InputError(where, "x must increase from vertex to vertex; vertex " +
                                  std::to_string(i + 1) +
                                  " has x = " + std::to_string(vertices_[i][0]) +
                                  " after x = " + std::to_string(vertices_[i - 1][0]));
}

Real Polyline::at(Real x) const {
  if (vertices_.empty()) return 0;
  if (x <= vertices_.front()[0]) return vertices_.front()[1];
  if (x >= vertices_.back()[0]) return vertices_.back()[1];
  // First vertex with x_i > x; the segment is [i-1, i].
  const auto next = std::upper_bound(vertices_.begin(), vertices_.end(), x,
                                     [](Real value, const auto& v) { return value < v[0]; });
  const auto& b = *next;
  const auto& a = *(next - 1);
  const Real t = (x - a[0]) / (b[0] - a[0]);
  return a[1] + t * (b[1] - a[1]);
}

}  // namespace argine
