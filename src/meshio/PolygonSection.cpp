/// @file PolygonSection.cpp
/// The polygon cross-section generator: graph -> conforming triangles -> blocks by region
/// -> (quads) -> nodes and elements ordered for locality -> Mesh with box side sets.
#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <sstream>
#include <stdexcept>

#include "argine/core/Error.hpp"
#include "argine/meshio/MeshGenerators.hpp"
#include "argine/meshio/SectionGraph.hpp"
#include "argine/meshio/SectionTriangulator.hpp"

namespace argine {

namespace {

const std::string kWhere = "Mesh/Generate";
const std::string kEmptyBlock = "empty";

/// Each triangle of a 2h mesh becomes three quads: corner, edge midpoints and centroid.
/// Midpoints of shared edges are shared, so the quad mesh conforms where the triangles do.
void splitIntoQuads(const SectionTriangulation& tri, const std::vector<int>& tri_block,
                    std::vector<Point2>& points, std::vector<std::array<int, 4>>& quads,
                    std::vector<int>& quad_block) {
  points = tri.points;
  std::map<std::pair<int, int>, int> midpoint;
  auto midpointOf = [&](int a, int b) {
    const auto key = std::make_pair(std::min(a, b), std::max(a, b));
    const auto it = midpoint.find(key);
    if (it != midpoint.end()) return it->second;
    points.push_back({0.5 * (points[a][0] + points[b][0]), 0.5 * (points[a][1] + points[b][1])});
    const int m = static_cast<int>(points.size()) - 1;
    midpoint.emplace(key, m);
    return m;
  };
  for (std::size_t t = 0; t < tri.triangles.size(); ++t) {
    const auto& v = tri.triangles[t];
    const int m01 = midpointOf(v[0], v[1]), m12 = midpointOf(v[1], v[2]),
              m20 = midpointOf(v[2], v[0]);
    points.push_back({(points[v[0]][0] + points[v[1]][0] + points[v[2]][0]) / 3,
                      (points[v[0]][1] + points[v[1]][1] + points[v[2]][1]) / 3});
    const int g = static_cast<int>(points.size()) - 1;
    quads.push_back({v[0], m01, g, m20});
    quads.push_back({v[1], m12, g, m01});
    quads.push_back({v[2], m20, g, m12});
    for (int k = 0; k < 3; ++k) quad_block.push_back(tri_block[t]);
  }
}

/// Renumbers nodes and elements along stripes of width h across the long side of the box,
/// so neighbours in space are neighbours in memory (and matrix bandwidth stays small).
void orderForLocality(std::vector<Point2>& points, std::vector<std::array<int, 4>>& elements,
                      std::vector<int>& element_block, int nv, const GeneratorSpec& spec) {
  const int along =
      (spec.upper_right[0] - spec.lower_left[0] >= spec.upper_right[1] - spec.lower_left[1]) ? 0
                                                                                             : 1;
  auto key = [&](const Point2& p) {
    const Real stripe = std::floor((p[along] - spec.lower_left[along]) / spec.element_size);
    return std::make_pair(stripe, p[1 - along]);
  };
  std::vector<int> order(points.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(),
                   [&](int a, int b) { return key(points[a]) < key(points[b]); });
  std::vector<int> new_index(points.size());
  std::vector<Point2> sorted_points(points.size());
  for (std::size_t i = 0; i < order.size(); ++i) {
    new_index[order[i]] = static_cast<int>(i);
    sorted_points[i] = points[order[i]];
  }
  points = std::move(sorted_points);
  for (auto& element : elements)
    for (int k = 0; k < nv; ++k) element[k] = new_index[element[k]];

  std::vector<std::pair<Real, Real>> element_key;
  for (const auto& element : elements) {
    Point2 centre{0, 0};
    for (int k = 0; k < nv; ++k)
      for (int d = 0; d < 2; ++d) centre[d] += points[element[k]][d] / nv;
    element_key.push_back(key(centre));
  }
  std::vector<int> element_order(elements.size());
  std::iota(element_order.begin(), element_order.end(), 0);
  std::stable_sort(element_order.begin(), element_order.end(),
                   [&](int a, int b) { return element_key[a] < element_key[b]; });
  std::vector<std::array<int, 4>> sorted_elements;
  std::vector<int> sorted_blocks;
  for (int e : element_order) {
    sorted_elements.push_back(elements[e]);
    sorted_blocks.push_back(element_block[e]);
  }
  elements = std::move(sorted_elements);
  element_block = std::move(sorted_blocks);
}

}  // namespace

Mesh generatePolygonSection(const GeneratorSpec& spec) {
  const SectionGraph graph = buildSectionGraph(spec);
  if (spec.regions.empty())
    throw InputError(kWhere + "/Regions", "a polygon section needs at least one region");
  const Real h = spec.element_size;
  const Real box_area =
      (spec.upper_right[0] - spec.lower_left[0]) * (spec.upper_right[1] - spec.lower_left[1]);
  if (box_area / (h * h * std::sqrt(3.0) / 4) > 5e7)
    throw InputError(kWhere + "/Element Size (m)",
                     "element size " + std::to_string(h) +
                         " m gives more than the generator's limit of 5e7 elements");

  const bool quads = spec.element == ElementType::Quad4;
  SectionTriangulation tri;
  try {
    tri = triangulateSection(graph, quads ? 2 * h : h);
  } catch (const std::logic_error& error) {
    // Only reachable with edges closer than the merge tolerance that do not touch.
    throw InputError(kWhere + "/Regions",
                     std::string("the regions could not be meshed (") + error.what() +
                         "); do two region edges nearly touch (closer than 1e-7 box sizes)?");
  }

  // Blocks: distinct region block names in order of appearance, then "empty".
  std::vector<std::string> block_names;
  std::vector<int> region_block;
  for (const auto& name : graph.region_blocks) {
    auto it = std::find(block_names.begin(), block_names.end(), name);
    if (it == block_names.end()) it = block_names.insert(block_names.end(), name);
    region_block.push_back(static_cast<int>(it - block_names.begin()));
  }
  const int empty_block = static_cast<int>(
      std::find(block_names.begin(), block_names.end(), kEmptyBlock) - block_names.begin());
  if (empty_block == static_cast<int>(block_names.size())) block_names.push_back(kEmptyBlock);

  // The mesh conforms to every region edge, so each triangle is wholly inside or outside
  // each region and its centroid decides.
  std::vector<int> tri_block(tri.triangles.size(), empty_block);
  for (std::size_t t = 0; t < tri.triangles.size(); ++t) {
    const auto& v = tri.triangles[t];
    const Point2 centroid{(tri.points[v[0]][0] + tri.points[v[1]][0] + tri.points[v[2]][0]) / 3,
                          (tri.points[v[0]][1] + tri.points[v[1]][1] + tri.points[v[2]][1]) / 3};
    int owner = -1;
    for (std::size_t r = 0; r < graph.regions.size(); ++r) {
      if (!isInsidePolygon(centroid, graph.regions[r])) continue;
      if (owner >= 0) {
        std::ostringstream what;
        what << "regions " << graph.region_blocks[owner] << " and " << graph.region_blocks[r]
             << " overlap near (" << centroid[0] << ", " << centroid[1] << ")";
        throw InputError(kWhere + "/Regions", what.str());
      }
      owner = static_cast<int>(r);
    }
    if (owner >= 0) tri_block[t] = region_block[owner];
  }

  std::vector<Point2> points;
  std::vector<std::array<int, 4>> elements;
  std::vector<int> element_block;
  if (quads) {
    splitIntoQuads(tri, tri_block, points, elements, element_block);
  } else {
    points = tri.points;
    for (const auto& t : tri.triangles) elements.push_back({t[0], t[1], t[2], -1});
    element_block = tri_block;
  }
  if (std::count(element_block.begin(), element_block.end(), empty_block) == 0 &&
      block_names.back() == kEmptyBlock && empty_block == static_cast<int>(block_names.size()) - 1)
    block_names.pop_back();  // the regions fill the box
  orderForLocality(points, elements, element_block, nodesPerElement(spec.element), spec);
  Mesh mesh = assembleMesh(spec.element, points, elements, element_block, block_names);
  addBoxSideSets(mesh, spec.lower_left, spec.upper_right);
  return mesh;
}

}  // namespace argine
