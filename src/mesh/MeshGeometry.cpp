#include "argine/mesh/MeshGeometry.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <vector>

#include "argine/core/Error.hpp"
#include "argine/mesh/MeshFolds.hpp"

namespace argine {

namespace {

template <class Shape>
void fillAreas(const Mesh& mesh, const Kokkos::View<Real*, MemSpace>& areas) {
  const auto coordinates = mesh.coordinates;
  const auto connectivity = mesh.connectivity;
  Kokkos::parallel_for(
      "elementAreas", Kokkos::RangePolicy<ExecSpace>(0, mesh.numElements()),
      KOKKOS_LAMBDA(const int e) {
        Real X[Shape::kNodes][kDim];
        gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
        areas(e) = elementArea<Shape>(X);
      });
}

template <class Shape>
void fillSizes(const Mesh& mesh, const Kokkos::View<Real*, MemSpace>& sizes) {
  const auto coordinates = mesh.coordinates;
  const auto connectivity = mesh.connectivity;
  Kokkos::parallel_for(
      "elementCharacteristicSizes", Kokkos::RangePolicy<ExecSpace>(0, mesh.numElements()),
      KOKKOS_LAMBDA(const int e) {
        Real X[Shape::kNodes][kDim];
        gatherElementCoordinates<Shape>(coordinates, connectivity, e, X);
        sizes(e) = elementMinimumHeight<Shape>(X);
      });
}

/// One element side, keyed by its sorted node pair.
struct Side {
  int low, high, element, side;
  bool operator<(const Side& o) const {
    if (low != o.low) return low < o.low;
    if (high != o.high) return high < o.high;
    if (element != o.element) return element < o.element;
    return side < o.side;
  }
};

/// Host-side edge matching. Fills neighbours (elements x sides, -1 on the boundary) and
/// returns the first side shared by more than two elements (element = -1 if none).
template <class Connectivity>
Side matchSides(const Connectivity& connectivity, int elements, int nodes_per_element,
                std::vector<int>& neighbours) {
  std::vector<Side> sides;
  sides.reserve(static_cast<size_t>(elements) * nodes_per_element);
  for (int e = 0; e < elements; ++e)
    for (int s = 0; s < nodes_per_element; ++s) {
      const int a = connectivity(e, s), b = connectivity(e, (s + 1) % nodes_per_element);
      sides.push_back({std::min(a, b), std::max(a, b), e, s});
    }
  std::sort(sides.begin(), sides.end());
  neighbours.assign(sides.size(), -1);
  Side overshared{-1, -1, -1, -1};
  for (size_t i = 0; i < sides.size();) {
    size_t j = i + 1;
    while (j < sides.size() && sides[j].low == sides[i].low && sides[j].high == sides[i].high) ++j;
    if (j - i == 2) {
      const Side& p = sides[i];
      const Side& q = sides[i + 1];
      neighbours[static_cast<size_t>(p.element) * nodes_per_element + p.side] = q.element;
      neighbours[static_cast<size_t>(q.element) * nodes_per_element + q.side] = p.element;
    } else if (j - i > 2 && (overshared.element < 0 || sides[i + 2].element < overshared.element)) {
      overshared = sides[i + 2];
    }
    i = j;
  }
  return overshared;
}

std::string describeSide(const Side& side) {
  std::ostringstream out;
  out << "the side joining nodes " << side.low + 1 << " and " << side.high + 1
      << " (1-based) is shared by more than two elements (element " << side.element + 1
      << " is the third); a 2D mesh side belongs to at most two elements";
  return out.str();
}

std::string blockNameOf(const Mesh& mesh, int block) {
  if (block >= 0 && block < static_cast<int>(mesh.blocks.size()))
    return "'" + mesh.blocks[block].name + "'";
  return "<none>";
}

}  // namespace

Kokkos::View<Real*, MemSpace> elementAreas(const Mesh& mesh) {
  Kokkos::View<Real*, MemSpace> areas("element_area", mesh.numElements());
  if (mesh.type == ElementType::Tri3)
    fillAreas<Tri3>(mesh, areas);
  else
    fillAreas<Quad4>(mesh, areas);
  return areas;
}

Kokkos::View<Real*, MemSpace> elementCharacteristicSizes(const Mesh& mesh) {
  Kokkos::View<Real*, MemSpace> sizes("element_size", mesh.numElements());
  if (mesh.type == ElementType::Tri3)
    fillSizes<Tri3>(mesh, sizes);
  else
    fillSizes<Quad4>(mesh, sizes);
  return sizes;
}

Kokkos::View<int**, MemSpace> computeElementNeighbours(const Mesh& mesh) {
  const int elements = mesh.numElements(), per = mesh.nodesPerElement();
  const auto connectivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  std::vector<int> list;
  const Side overshared = matchSides(connectivity, elements, per, list);
  if (overshared.element >= 0) throw InputError("mesh", describeSide(overshared));

  Kokkos::View<int**, MemSpace> neighbours("element_neighbours", elements, per);
  auto host = Kokkos::create_mirror_view(neighbours);
  for (int e = 0; e < elements; ++e)
    for (int s = 0; s < per; ++s) host(e, s) = list[static_cast<size_t>(e) * per + s];
  Kokkos::deep_copy(neighbours, host);
  return neighbours;
}

void checkMeshQuality(const Mesh& mesh, const std::string& source) {
  const int elements = mesh.numElements(), per = mesh.nodesPerElement();
  const int nodes = mesh.numNodes();
  const auto coordinates =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto connectivity =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  const auto element_block =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.element_block);

  auto fail = [&](int e, const std::string& problem) {
    const int block = e < static_cast<int>(element_block.extent(0)) ? element_block(e) : -1;
    std::ostringstream out;
    out << "element " << e + 1 << " (1-based) in block " << blockNameOf(mesh, block) << " "
        << problem;
    throw InputError(source, out.str());
  };

  for (int e = 0; e < elements; ++e) {
    Real X[4][kDim];
    for (int a = 0; a < per; ++a) {
      const int n = connectivity(e, a);
      if (n < 0 || n >= nodes) {
        std::ostringstream out;
        out << "refers to node " << n + 1 << " but the mesh has " << nodes << " nodes";
        fail(e, out.str());
      }
      X[a][0] = coordinates(n, 0);
      X[a][1] = coordinates(n, 1);
    }
    Real longest_squared = 0.0;
    for (int a = 0; a < per; ++a) {
      const int b = (a + 1) % per;
      const Real dx = X[b][0] - X[a][0], dy = X[b][1] - X[a][1];
      longest_squared = std::max(longest_squared, dx * dx + dy * dy);
    }
    const Real area = per == 3 ? elementArea<Tri3>(X) : elementArea<Quad4>(X);
    // Round-off in the area is ~ eps * side^2; far above that, the element has real extent.
    if (!(std::fabs(area) > 1e-12 * longest_squared)) {
      std::ostringstream out;
      out << "is degenerate (area " << area << " m^2, longest side " << std::sqrt(longest_squared)
          << " m): its nodes are collinear or coincide";
      fail(e, out.str());
    }
    if (area < 0.0) {
      std::ostringstream out;
      out << "is inverted (signed area " << area
          << " m^2): its nodes must be listed counter-clockwise";
      fail(e, out.str());
    }
    if (per == 4) {
      // det J at corner a of a bilinear quad = (X_{a+1} - X_a) x (X_{a-1} - X_a) / 4.
      for (int a = 0; a < per; ++a) {
        const int next = (a + 1) % per, prev = (a + per - 1) % per;
        const Real cross = (X[next][0] - X[a][0]) * (X[prev][1] - X[a][1]) -
                           (X[next][1] - X[a][1]) * (X[prev][0] - X[a][0]);
        if (!(cross > 1e-12 * longest_squared)) {
          std::ostringstream out;
          out << "is non-convex or folded at its local node " << a + 1 << " (corner Jacobian "
              << 0.25 * cross << "): a bilinear quadrilateral must be strictly convex";
          fail(e, out.str());
        }
      }
    }
  }

  std::vector<int> list;
  const Side overshared = matchSides(connectivity, elements, per, list);
  if (overshared.element >= 0) throw InputError(source, describeSide(overshared));
  checkNoFoldedElements(mesh, source);  // (P8) tangled meshes
}

}  // namespace argine
