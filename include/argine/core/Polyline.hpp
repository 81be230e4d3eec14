#pragma once
/// @file Polyline.hpp
/// A curve y(x) given as a polyline through points with strictly increasing x: the ground and
/// phreatic surfaces of the K0 procedure (thesis Ch. 4 Sec. 5.1), a pore-pressure table, the
/// ground, layer tops and phreatic line of a limit-equilibrium section (P13). Linear between
/// the points, continued as a constant (the end values) beyond the first and last x, which is
/// what a surface drawn to the edge of a model means.

#include <array>
#include <string>
#include <vector>

#include "argine/core/Types.hpp"

namespace argine {

struct Polyline {
  std::vector<Real> x;  ///< abscissae (m), strictly increasing
  std::vector<Real> y;  ///< ordinates, one per abscissa

  Polyline() = default;
  /// Throws std::invalid_argument unless as many x as y, at least one, x strictly increasing.
  Polyline(std::vector<Real> xs, std::vector<Real> ys);
  /// From (x, y) vertices of a deck key; throws InputError(where, ...) without vertices or
  /// when x does not strictly increase.
  Polyline(const std::vector<std::array<Real, 2>>& vertices, const std::string& where);

  /// y at xq: linear between the points, constant beyond the ends; 0 when empty.
  Real at(Real xq) const;
  bool empty() const { return x.empty(); }
  Real xFirst() const { return x.front(); }
  Real xLast() const { return x.back(); }
};

}  // namespace argine
