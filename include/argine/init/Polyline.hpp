#pragma once
/// @file Polyline.hpp
/// A surface y(x) given as a polyline of (x, y) vertices with increasing x (the ground and
/// phreatic surfaces of the K0 procedure, thesis Ch. 4 Sec. 5.1). Linear between vertices,
/// constant beyond the first and last vertex (the surface continues horizontally).

#include <array>
#include <string>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

class Polyline {
 public:
  Polyline() = default;
  /// Throws InputError(where, ...) without vertices or when x does not strictly increase.
  Polyline(std::vector<std::array<Real, 2>> vertices, const std::string& where);

  /// y at x (m): linear interpolation, constant continuation outside [x_first, x_last].
  Real at(Real x) const;
  bool empty() const { return vertices_.empty(); }
  const std::vector<std::array<Real, 2>>& vertices() const { return vertices_; }

 private:
  std::vector<std::array<Real, 2>> vertices_;
};

}  // namespace argine
