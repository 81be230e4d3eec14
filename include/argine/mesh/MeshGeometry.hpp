#pragma once
/// @file MeshGeometry.hpp
/// Per-element geometry of the background mesh (areas, characteristic sizes), edge
/// adjacency, and the quality check run on every mesh before a simulation starts.

#include <string>

#include "argine/core/Types.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/mesh/ShapeFunctions.hpp"

namespace argine {

/// Minimum height of an element: over its sides, the largest perpendicular distance from
/// the side's line to a node not on that side, minimised over the sides. For a triangle
/// this is the shortest altitude 2A / (longest side); for a rectangle the shorter side.
///
/// Why not sqrt(area): explicit time-step criteria (CFL, consolidation; thesis 4.61-4.64)
/// need the shortest distance a wave or diffusion front crosses inside an element. A sliver
/// of aspect ratio r has sqrt(A) ~ sqrt(r) times its thickness, so sqrt(area) would give a
/// step too large by that factor; the minimum height equals the thickness (Anura3D also
/// uses the minimum altitude).
template <class Shape>
KOKKOS_INLINE_FUNCTION Real elementMinimumHeight(const Real X[][kDim]) {
  Real smallest = 0.0;
  for (int a = 0; a < Shape::kNodes; ++a) {
    const int b = (a + 1) % Shape::kNodes;
    const Real ex = X[b][0] - X[a][0], ey = X[b][1] - X[a][1];
    const Real length = Kokkos::Experimental::sqrt(ex * ex + ey * ey);
    Real height = 0.0;
    for (int c = 0; c < Shape::kNodes; ++c) {
      if (c == a || c == b) continue;
      const Real cross = ex * (X[c][1] - X[a][1]) - ey * (X[c][0] - X[a][0]);
      const Real distance = Kokkos::Experimental::fabs(cross) / length;
      if (distance > height) height = distance;
    }
    if (a == 0 || height < smallest) smallest = height;
  }
  return smallest;
}

/// Signed area of every element (m^2 per metre thickness), positive when counter-clockwise.
Kokkos::View<Real*, MemSpace> elementAreas(const Mesh& mesh);

/// Characteristic size of every element = elementMinimumHeight (m); see its comment for
/// why this and not sqrt(area). Time-step criteria use it.
Kokkos::View<Real*, MemSpace> elementCharacteristicSizes(const Mesh& mesh);

/// Edge adjacency: neighbours(e, s) is the element sharing side s of e (side s joins local
/// nodes s and (s+1) % nodes), or -1 on the mesh boundary. Elements match by node index,
/// so coincident but distinct nodes are not joined. Throws InputError("mesh", ...) when an
/// edge is shared by more than two elements (checkMeshQuality reports it with the file).
Kokkos::View<int**, MemSpace> computeElementNeighbours(const Mesh& mesh);

/// Throws InputError(source, ...) naming the first bad element (1-based index and block)
/// when an element is degenerate (|area| <= 1e-12 longest side^2), inverted (clockwise
/// nodes) or, for Quad4, non-convex (a corner with non-positive Jacobian, where the
/// bilinear map folds over); or when an edge is shared by more than two elements; or when
/// a connectivity entry is not a node index; or when two elements overlap (MeshFolds.hpp).
void checkMeshQuality(const Mesh& mesh, const std::string& source);

}  // namespace argine
