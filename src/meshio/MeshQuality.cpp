#include "argine/meshio/MeshQuality.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

#include "argine/meshio/Geometry2D.hpp"

namespace argine {

namespace {
std::vector<Point2> corners(const Kokkos::View<Real* [kDim], Kokkos::HostSpace>& x,
                            const Kokkos::View<int**, Kokkos::HostSpace>& conn, int e, int nv) {
  std::vector<Point2> result(nv);
  for (int k = 0; k < nv; ++k) result[k] = {x(conn(e, k), 0), x(conn(e, k), 1)};
  return result;
}
}  // namespace

MeshQuality measureQuality(const Mesh& mesh) {
  Kokkos::View<Real* [kDim], Kokkos::HostSpace> x("x", mesh.numNodes());
  Kokkos::View<int**, Kokkos::HostSpace> conn("conn", mesh.numElements(), mesh.nodesPerElement());
  Kokkos::deep_copy(x, mesh.coordinates);
  Kokkos::deep_copy(conn, mesh.connectivity);
  const int nv = mesh.nodesPerElement();

  MeshQuality quality;
  quality.min_angle_degrees = 180;
  quality.min_area = std::numeric_limits<Real>::max();
  Point2 lo{std::numeric_limits<Real>::max(), std::numeric_limits<Real>::max()};
  Point2 hi{-lo[0], -lo[1]};
  for (int n = 0; n < mesh.numNodes(); ++n)
    for (int d = 0; d < 2; ++d) {
      lo[d] = std::min(lo[d], x(n, d));
      hi[d] = std::max(hi[d], x(n, d));
    }
  // Directed edge (a, b) -> number of elements using it in that direction.
  std::map<std::pair<int, int>, int> directed;
  for (int e = 0; e < mesh.numElements(); ++e) {
    const auto p = corners(x, conn, e, nv);
    const Real area = signedArea(p);
    quality.min_area = std::min(quality.min_area, area);
    quality.total_area += area;
    bool ccw = true;
    for (int k = 0; k < nv; ++k) {
      const Point2& prev = p[(k + nv - 1) % nv];
      const Point2& next = p[(k + 1) % nv];
      const Real angle = angleDegrees(prev, p[k], next);
      quality.min_angle_degrees = std::min(quality.min_angle_degrees, angle);
      quality.max_angle_degrees = std::max(quality.max_angle_degrees, angle);
      if (!(orientation(prev, p[k], next) > 0)) ccw = false;
      ++directed[{conn(e, k), conn(e, (k + 1) % nv)}];
    }
    if (!ccw) ++quality.non_ccw_elements;
  }
  const Real tolerance = 1e-9 * std::max(hi[0] - lo[0], hi[1] - lo[1]);
  auto onBox = [&](int a, int b) {
    for (int d = 0; d < 2; ++d)
      for (Real side : {lo[d], hi[d]})
        if (std::abs(x(a, d) - side) <= tolerance && std::abs(x(b, d) - side) <= tolerance)
          return true;
    return false;
  };
  for (const auto& [edge, count] : directed) {
    const auto reverse = directed.find({edge.second, edge.first});
    const int opposite = reverse == directed.end() ? 0 : reverse->second;
    const bool matched =
        count == 1 && (opposite == 1 || (opposite == 0 && onBox(edge.first, edge.second)));
    if (!matched) ++quality.unmatched_edges;
  }
  return quality;
}

std::vector<Real> blockAreas(const Mesh& mesh) {
  Kokkos::View<Real* [kDim], Kokkos::HostSpace> x("x", mesh.numNodes());
  Kokkos::View<int**, Kokkos::HostSpace> conn("conn", mesh.numElements(), mesh.nodesPerElement());
  Kokkos::deep_copy(x, mesh.coordinates);
  Kokkos::deep_copy(conn, mesh.connectivity);
  std::vector<Real> areas;
  for (const auto& block : mesh.blocks) {
    Real area = 0;
    for (int e : block.elements) area += signedArea(corners(x, conn, e, mesh.nodesPerElement()));
    areas.push_back(area);
  }
  return areas;
}

}  // namespace argine
