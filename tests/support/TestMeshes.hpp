#pragma once
// Small meshes built inside tests (no files): hand-made triangulations and structured
// grids, optionally perturbed and with cells removed (L-shapes, holes).

#include <array>
#include <cmath>
#include <functional>
#include <random>
#include <string>
#include <vector>

#include "argine/mesh/Mesh.hpp"

namespace argine::test {

using Point2 = std::array<Real, 2>;

/// Mesh from node coordinates and connectivity; block_of[e] indexes block_names
/// (all elements in the first block when block_of is empty).
inline Mesh makeMesh(ElementType type, const std::vector<Point2>& nodes,
                     const std::vector<std::vector<int>>& elements,
                     const std::vector<int>& block_of = {},
                     const std::vector<std::string>& block_names = {"block_1"}) {
  Mesh mesh;
  mesh.type = type;
  const int n = static_cast<int>(nodes.size()), ne = static_cast<int>(elements.size());
  const int per = nodesPerElement(type);
  mesh.coordinates = Kokkos::View<Real* [kDim], MemSpace>("coordinates", n);
  mesh.connectivity = Kokkos::View<int**, MemSpace>("connectivity", ne, per);
  mesh.element_block = Kokkos::View<int*, MemSpace>("element_block", ne);
  auto x = Kokkos::create_mirror_view(mesh.coordinates);
  auto c = Kokkos::create_mirror_view(mesh.connectivity);
  auto b = Kokkos::create_mirror_view(mesh.element_block);
  for (int i = 0; i < n; ++i) {
    x(i, 0) = nodes[i][0];
    x(i, 1) = nodes[i][1];
  }
  for (size_t k = 0; k < block_names.size(); ++k)
    mesh.blocks.push_back({block_names[k], static_cast<int>(k) + 1, {}});
  for (int e = 0; e < ne; ++e) {
    for (int a = 0; a < per; ++a) c(e, a) = elements[e][a];
    b(e) = block_of.empty() ? 0 : block_of[e];
    mesh.blocks[b(e)].elements.push_back(e);
  }
  Kokkos::deep_copy(mesh.coordinates, x);
  Kokkos::deep_copy(mesh.connectivity, c);
  Kokkos::deep_copy(mesh.element_block, b);
  return mesh;
}

/// Options of a structured grid of nx x ny cells over [x0, x0+lx] x [y0, y0+ly].
struct GridOptions {
  int nx = 4, ny = 4;
  Real x0 = 0.0, y0 = 0.0, lx = 1.0, ly = 1.0;
  Real perturbation = 0.0;  ///< interior nodes moved by up to this fraction of a cell
  unsigned seed = 1;
  /// Keep cell (i, j)? Default: all cells.
  std::function<bool(int, int)> keep = [](int, int) { return true; };
  /// Block of cell (i, j) (index into block_names).
  std::function<int(int, int)> block = [](int, int) { return 0; };
  std::vector<std::string> block_names = {"block_1"};
};

/// Structured grid of quads, or of triangles (each cell split along alternating diagonals).
inline Mesh structuredMesh(ElementType type, const GridOptions& o) {
  const Real hx = o.lx / o.nx, hy = o.ly / o.ny;
  std::mt19937 random(o.seed);
  std::uniform_real_distribution<Real> shift(-o.perturbation, o.perturbation);
  std::vector<Point2> nodes;
  for (int j = 0; j <= o.ny; ++j)
    for (int i = 0; i <= o.nx; ++i) {
      Point2 p{o.x0 + i * hx, o.y0 + j * hy};
      const Real dx = shift(random), dy = shift(random);
      if (i > 0 && i < o.nx) p[0] += dx * hx;
      if (j > 0 && j < o.ny) p[1] += dy * hy;
      nodes.push_back(p);
    }
  auto id = [&](int i, int j) { return j * (o.nx + 1) + i; };
  std::vector<std::vector<int>> elements;
  std::vector<int> blocks;
  for (int j = 0; j < o.ny; ++j)
    for (int i = 0; i < o.nx; ++i) {
      if (!o.keep(i, j)) continue;
      const int n00 = id(i, j), n10 = id(i + 1, j), n11 = id(i + 1, j + 1), n01 = id(i, j + 1);
      if (type == ElementType::Quad4) {
        elements.push_back({n00, n10, n11, n01});
        blocks.push_back(o.block(i, j));
      } else if ((i + j) % 2 == 0) {
        elements.push_back({n00, n10, n11});
        elements.push_back({n00, n11, n01});
        blocks.insert(blocks.end(), 2, o.block(i, j));
      } else {
        elements.push_back({n00, n10, n01});
        elements.push_back({n10, n11, n01});
        blocks.insert(blocks.end(), 2, o.block(i, j));
      }
    }
  return makeMesh(type, nodes, elements, blocks, o.block_names);
}

/// Star-shaped (non-convex) fan: centre node 0 at the origin and 8 ring nodes at 45 degree
/// steps with radii alternating 1 and 0.4; triangle k = (0, k+1, k+2).
inline Mesh starFanMesh() {
  std::vector<Point2> nodes{{0.0, 0.0}};
  const Real pi = 3.14159265358979323846;
  for (int k = 0; k < 8; ++k) {
    const Real r = k % 2 == 0 ? 1.0 : 0.4, angle = k * pi / 4.0;
    nodes.push_back({r * std::cos(angle), r * std::sin(angle)});
  }
  std::vector<std::vector<int>> elements;
  for (int k = 0; k < 8; ++k) elements.push_back({0, 1 + k, 1 + (k + 1) % 8});
  return makeMesh(ElementType::Tri3, nodes, elements);
}

/// L-shaped domain [0,2]^2 minus [1,2]x[1,2], 8 x 8 cells, perturbed.
inline GridOptions lShapeOptions(Real perturbation = 0.2) {
  GridOptions o;
  o.nx = 8;
  o.ny = 8;
  o.lx = 2.0;
  o.ly = 2.0;
  o.perturbation = perturbation;
  o.keep = [](int i, int j) { return i < 4 || j < 4; };
  return o;
}

}  // namespace argine::test
