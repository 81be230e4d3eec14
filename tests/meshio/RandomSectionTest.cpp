// Robustness of the polygon-section generator on random layered sections: layers with
// piecewise-linear interfaces (vertices at random places, so interfaces meet the box sides
// at arbitrary heights) and a levee standing on the top interface, at random element sizes
// from 1% to 21% of the box height. Every mesh must be valid and conforming; the smallest
// angle may only fall below 20 degrees where the input itself has a smaller angle.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "argine/core/Error.hpp"
#include "argine/meshio/Geometry2D.hpp"
#include "argine/meshio/MeshGenerators.hpp"
#include "argine/meshio/MeshQuality.hpp"
#include "argine/meshio/SectionGraph.hpp"

namespace argine {
namespace {

/// Smallest angle between two graph edges meeting at a vertex (degrees).
Real smallestInputAngle(const GeneratorSpec& spec) {
  const SectionGraph graph = buildSectionGraph(spec);
  Real smallest = 360;
  for (std::size_t v = 0; v < graph.vertices.size(); ++v) {
    std::vector<Real> directions;
    for (const auto& s : graph.segments)
      if (s[0] == static_cast<int>(v) || s[1] == static_cast<int>(v)) {
        const Point2& other = graph.vertices[s[0] == static_cast<int>(v) ? s[1] : s[0]];
        directions.push_back(
            std::atan2(other[1] - graph.vertices[v][1], other[0] - graph.vertices[v][0]));
      }
    if (directions.size() < 2) continue;
    std::sort(directions.begin(), directions.end());
    Real gap = directions.front() + 2 * M_PI - directions.back();
    for (std::size_t k = 0; k + 1 < directions.size(); ++k)
      gap = std::min(gap, directions[k + 1] - directions[k]);
    smallest = std::min(smallest, gap * 180 / M_PI);
  }
  return smallest;
}

GeneratorSpec randomSection(std::mt19937& random, int trial) {
  std::uniform_real_distribution<Real> uniform(0.0, 1.0);
  GeneratorSpec spec;
  spec.kind = GeneratorSpec::Kind::Polygon;
  spec.element = trial % 3 == 0 ? ElementType::Quad4 : ElementType::Tri3;
  const Real width = 5 + 20 * uniform(random), height = 2 + 8 * uniform(random);
  spec.upper_right = {width, height};
  spec.element_size = std::min(width, height) * (0.01 + 0.2 * uniform(random));
  // Interfaces: increasing base heights plus bumps small enough never to cross.
  const int layers = 1 + trial % 3;
  std::vector<std::vector<Point2>> interfaces{{{0, 0}, {width, 0}}};
  for (int l = 1; l <= layers; ++l) {
    const Real base = height * 0.4 * l / layers;
    const Real bump = 0.1 * height / layers;
    const int inner = static_cast<int>(random() % 4);
    std::vector<Point2> line{{0, base + bump * uniform(random)}};
    for (int k = 1; k <= inner; ++k)
      line.push_back({width * (k + 0.5 * (uniform(random) - 0.5)) / (inner + 1),
                      base + bump * uniform(random)});
    line.push_back({width, base + bump * uniform(random)});
    interfaces.push_back(line);
  }
  for (int l = 0; l < layers; ++l) {
    PolygonRegion region{"layer" + std::to_string(l), interfaces[l]};
    region.vertices.insert(region.vertices.end(), interfaces[l + 1].rbegin(),
                           interfaces[l + 1].rend());
    spec.regions.push_back(region);
  }
  // A levee on the first piece of the top interface.
  const auto& top = interfaces.back();
  auto topAt = [&](Real x) {
    return top[0][1] + (top[1][1] - top[0][1]) * (x - top[0][0]) / (top[1][0] - top[0][0]);
  };
  const Real x0 = top[0][0] + 0.1 * (top[1][0] - top[0][0]);
  const Real x1 = top[0][0] + 0.9 * (top[1][0] - top[0][0]);
  const Real crest =
      std::max(topAt(x0), topAt(x1)) + 0.05 * height + 0.3 * height * uniform(random);
  const Real slope = 0.3 + 0.6 * uniform(random);
  const Real c0 = x0 + 0.5 * (crest - topAt(x0)) / slope;
  const Real c1 = x1 - 0.5 * (crest - topAt(x1)) / slope;
  if (crest < height && c1 > c0)
    spec.regions.push_back({"levee", {{x0, topAt(x0)}, {x1, topAt(x1)}, {c1, crest}, {c0, crest}}});
  return spec;
}

TEST(RandomSections, AreValidConformingAndAsWellShapedAsTheInputAllows) {
  std::mt19937 random(2024);
  Real worst_margin = 180;
  for (int trial = 0; trial < 24; ++trial) {
    const GeneratorSpec spec = randomSection(random, trial);
    SCOPED_TRACE("trial " + std::to_string(trial) + ", h = " + std::to_string(spec.element_size));
    const Mesh mesh = generateMesh(spec);
    const MeshQuality quality = measureQuality(mesh);
    EXPECT_EQ(quality.non_ccw_elements, 0);
    EXPECT_GT(quality.min_area, 0.0);
    EXPECT_EQ(quality.unmatched_edges, 0);
    const std::vector<Real> areas = blockAreas(mesh);
    for (const auto& region : spec.regions) {
      const Real expected = std::abs(signedArea(region.vertices));
      const ElementBlock* block = mesh.findBlock(region.block);
      ASSERT_NE(block, nullptr);
      EXPECT_NEAR(areas[block - mesh.blocks.data()], expected, 1e-10 * expected) << region.block;
    }
    if (mesh.type == ElementType::Tri3) {
      const Real allowed = std::min<Real>(20, smallestInputAngle(spec)) - 3;
      EXPECT_GE(quality.min_angle_degrees, allowed);
      worst_margin = std::min(worst_margin, quality.min_angle_degrees - allowed);
    }
  }
  std::printf("    smallest margin above min(20, input angle) - 3: %.2f deg\n", worst_margin);
}

}  // namespace
}  // namespace argine
