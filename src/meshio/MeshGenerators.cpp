/// @file MeshGenerators.cpp
/// Generator dispatch, the structured rectangle, and the shared assembly helpers.
#include "argine/meshio/MeshGenerators.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "argine/core/Error.hpp"
#include "argine/meshio/RectangleRegions.hpp"

namespace argine {

namespace {
const std::string kWhere = "Mesh/Generate";
/// Largest mesh a generator makes: beyond this a typo in the element size is more likely.
constexpr double kMaxElements = 5e7;
}  // namespace

Mesh generateMesh(const GeneratorSpec& spec) {
  return spec.kind == GeneratorSpec::Kind::Rectangle ? generateRectangle(spec)
                                                     : generatePolygonSection(spec);
}

Mesh assembleMesh(ElementType type, const std::vector<std::array<Real, 2>>& points,
                  const std::vector<std::array<int, 4>>& elements,
                  const std::vector<int>& element_block,
                  const std::vector<std::string>& block_names) {
  const int nv = nodesPerElement(type);
  std::vector<char> used(points.size(), 0);
  for (const auto& element : elements)
    for (int k = 0; k < nv; ++k) used.at(element[k]) = 1;
  std::vector<int> new_index(points.size(), -1);
  int num_nodes = 0;
  for (std::size_t p = 0; p < points.size(); ++p)
    if (used[p]) new_index[p] = num_nodes++;

  Mesh mesh;
  mesh.type = type;
  mesh.coordinates = Kokkos::View<Real* [kDim], MemSpace>("mesh coordinates", num_nodes);
  mesh.connectivity = Kokkos::View<int**, MemSpace>("mesh connectivity", elements.size(), nv);
  mesh.element_block = Kokkos::View<int*, MemSpace>("mesh element block", elements.size());
  auto coordinates = Kokkos::create_mirror_view(mesh.coordinates);
  auto connectivity = Kokkos::create_mirror_view(mesh.connectivity);
  auto block_of = Kokkos::create_mirror_view(mesh.element_block);
  for (std::size_t p = 0; p < points.size(); ++p)
    if (new_index[p] >= 0) {
      coordinates(new_index[p], 0) = points[p][0];
      coordinates(new_index[p], 1) = points[p][1];
    }
  for (std::size_t b = 0; b < block_names.size(); ++b)
    mesh.blocks.push_back({block_names[b], static_cast<int>(b) + 1, {}});
  // Elements are stored block by block, so the Exodus numbering equals the mesh numbering.
  int e = 0;
  for (std::size_t b = 0; b < block_names.size(); ++b)
    for (std::size_t i = 0; i < elements.size(); ++i) {
      if (element_block[i] != static_cast<int>(b)) continue;
      for (int k = 0; k < nv; ++k) connectivity(e, k) = new_index[elements[i][k]];
      block_of(e) = static_cast<int>(b);
      mesh.blocks[b].elements.push_back(e++);
    }
  if (e != static_cast<int>(elements.size()))
    throw std::invalid_argument("assembleMesh: element with a block index out of range");
  Kokkos::deep_copy(mesh.coordinates, coordinates);
  Kokkos::deep_copy(mesh.connectivity, connectivity);
  Kokkos::deep_copy(mesh.element_block, block_of);
  return mesh;
}

void addBoxSideSets(Mesh& mesh, const std::array<Real, 2>& lower_left,
                    const std::array<Real, 2>& upper_right) {
  auto x = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  auto conn = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  const Real tolerance =
      1e-9 * std::max(upper_right[0] - lower_left[0], upper_right[1] - lower_left[1]);
  struct Side {
    const char* name;
    int normal_axis;  // coordinate that is constant on the side
    Real value;
  };
  const Side sides[] = {{"left", 0, lower_left[0]},
                        {"right", 0, upper_right[0]},
                        {"bottom", 1, lower_left[1]},
                        {"top", 1, upper_right[1]}};
  const int nv = mesh.nodesPerElement();
  for (int s = 0; s < 4; ++s) {
    const int axis = sides[s].normal_axis, along = 1 - axis;
    auto on = [&](int node) { return std::abs(x(node, axis) - sides[s].value) <= tolerance; };
    NodeSet nodes{sides[s].name, s + 1, {}};
    for (int n = 0; n < mesh.numNodes(); ++n)
      if (on(n)) nodes.nodes.push_back(n);
    std::stable_sort(nodes.nodes.begin(), nodes.nodes.end(),
                     [&](int a, int b) { return x(a, along) < x(b, along); });
    std::vector<std::pair<Real, std::pair<int, int>>> found;  // (position, (element, side))
    for (int e = 0; e < mesh.numElements(); ++e)
      for (int k = 0; k < nv; ++k) {
        const int a = conn(e, k), b = conn(e, (k + 1) % nv);
        if (on(a) && on(b)) found.push_back({x(a, along) + x(b, along), {e, k}});
      }
    std::stable_sort(found.begin(), found.end(),
                     [](const auto& p, const auto& q) { return p.first < q.first; });
    SideSet set{sides[s].name, s + 1, {}, {}};
    for (const auto& f : found) {
      set.elements.push_back(f.second.first);
      set.sides.push_back(f.second.second);
    }
    mesh.node_sets.push_back(std::move(nodes));
    mesh.side_sets.push_back(std::move(set));
  }
}

Mesh generateRectangle(const GeneratorSpec& spec) {
  const auto& lo = spec.lower_left;
  const auto& hi = spec.upper_right;
  const Real h = spec.element_size;
  if (!(hi[0] > lo[0] && hi[1] > lo[1])) {
    std::ostringstream what;
    what << "the box needs upper right (" << hi[0] << ", " << hi[1]
         << ") above and right of lower left (" << lo[0] << ", " << lo[1] << ")";
    throw InputError(kWhere + "/Upper Right (m)", what.str());
  }
  if (!(h > 0))
    throw InputError(kWhere + "/Element Size (m)",
                     "the element size must be positive, got " + std::to_string(h));
  // The small allowance keeps exact multiples (1.0 / 0.1) from rounding up to one more.
  const Real cells_x = std::ceil((hi[0] - lo[0]) / h * (1 - 1e-12));
  const Real cells_y = std::ceil((hi[1] - lo[1]) / h * (1 - 1e-12));
  const bool triangles = spec.element == ElementType::Tri3;
  if (cells_x * cells_y * (triangles ? 2 : 1) > kMaxElements)
    throw InputError(kWhere + "/Element Size (m)",
                     "element size " + std::to_string(h) + " m gives " +
                         std::to_string(cells_x * cells_y) +
                         " cells, more than the generator's limit of 5e7 elements");
  const int nx = std::max(1, static_cast<int>(cells_x));
  const int ny = std::max(1, static_cast<int>(cells_y));

  std::vector<std::array<Real, 2>> points;
  for (int j = 0; j <= ny; ++j)
    for (int i = 0; i <= nx; ++i)
      points.push_back({i == nx ? hi[0] : lo[0] + (hi[0] - lo[0]) * i / nx,
                        j == ny ? hi[1] : lo[1] + (hi[1] - lo[1]) * j / ny});
  auto node = [nx](int i, int j) { return j * (nx + 1) + i; };
  std::vector<std::array<int, 4>> elements;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int n0 = node(i, j), n1 = node(i + 1, j), n2 = node(i + 1, j + 1), n3 = node(i, j + 1);
      if (!triangles) {
        elements.push_back({n0, n1, n2, n3});
      } else if ((i + j) % 2 == 0) {  // diagonal n0-n2
        elements.push_back({n0, n1, n2, -1});
        elements.push_back({n0, n2, n3, -1});
      } else {  // diagonal n1-n3
        elements.push_back({n0, n1, n3, -1});
        elements.push_back({n1, n2, n3, -1});
      }
    }
  Mesh mesh = assembleMesh(spec.element, points, elements, std::vector<int>(elements.size(), 0),
                           {spec.block});
  addBoxSideSets(mesh, lo, hi);
  if (!triangles) {
    // Spacing from the box, as the node coordinates are: node (i, j) = origin + (i, j) spacing
    // up to rounding (the last row and column sit exactly on the box).
    mesh.structured.cells[0] = nx;
    mesh.structured.cells[1] = ny;
    for (int d = 0; d < kDim; ++d) {
      mesh.structured.origin[d] = lo[d];
      mesh.structured.spacing[d] = (hi[d] - lo[d]) / (d == 0 ? nx : ny);
    }
  }
  if (!spec.regions.empty()) applyRectangleRegions(spec, mesh);
  return mesh;
}

}  // namespace argine
