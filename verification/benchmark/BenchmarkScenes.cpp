#include "BenchmarkScenes.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <random>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "argine/meshio/MeshGenerators.hpp"
#include "argine/physics/PointInitialisation.hpp"
#include "argine/points/PointFields.hpp"
#include "argine/points/Seeding.hpp"

namespace argine::benchmark {

namespace {

constexpr Real kCell = 0.1;  // element size (m)

/// Structured cells_x x cells_y grid of kCell squares from the origin; block "soil" is the
/// lower-left soil_x x soil_y cells, block "empty" the rest (left out when there is none).
/// Tri3 splits every cell along alternating diagonals. Box side and node sets "left",
/// "right", "bottom", "top".
Mesh structuredMesh(ElementType type, int cells_x, int cells_y, int soil_x, int soil_y) {
  std::vector<std::array<Real, 2>> nodes;
  for (int j = 0; j <= cells_y; ++j)
    for (int i = 0; i <= cells_x; ++i) nodes.push_back({i * kCell, j * kCell});
  auto node = [&](int i, int j) { return j * (cells_x + 1) + i; };
  std::vector<std::array<int, 4>> elements;
  std::vector<int> block;
  for (int j = 0; j < cells_y; ++j)
    for (int i = 0; i < cells_x; ++i) {
      const int a = node(i, j), b = node(i + 1, j), c = node(i + 1, j + 1), d = node(i, j + 1);
      const int in_block = i < soil_x && j < soil_y ? 0 : 1;
      if (type == ElementType::Quad4) {
        elements.push_back({a, b, c, d});
        block.push_back(in_block);
      } else if ((i + j) % 2 == 0) {
        elements.push_back({a, b, c, -1});
        elements.push_back({a, c, d, -1});
        block.insert(block.end(), 2, in_block);
      } else {
        elements.push_back({a, b, d, -1});
        elements.push_back({b, c, d, -1});
        block.insert(block.end(), 2, in_block);
      }
    }
  std::vector<std::string> names{"soil"};
  if (soil_x < cells_x || soil_y < cells_y) names.push_back("empty");
  Mesh mesh = assembleMesh(type, nodes, elements, block, names);
  addBoxSideSets(mesh, {0.0, 0.0}, {cells_x * kCell, cells_y * kCell});
  return mesh;
}

MaterialSpec soil(PhaseModel phase, int points_per_element) {
  MaterialSpec m;
  m.name = "soil";
  m.block = "soil";
  m.points_per_element = points_per_element;
  m.phase = phase;
  m.porosity = 0.4;
  m.solid_density = 2650;
  m.solid.model = SolidModel::LinearElastic;
  m.solid.youngs_modulus = 1e7;
  m.solid.poisson_ratio = 0.3;
  m.liquid.density = 1000;
  m.liquid.bulk_modulus = 2.2e9;
  m.conductivity.model = ConductivityModel::Constant;
  m.conductivity.saturated_conductivity = 1e-3;
  if (phase == PhaseModel::Unsaturated) {
    m.retention.model = RetentionModel::VanGenuchten;
    m.retention.reference_pressure = 1e4;  // p_ref (Pa)
    m.retention.lambda = 0.5;
    m.retention.saturation_min = 0.05;
    m.conductivity.model = ConductivityModel::Mualem;
    m.conductivity.use_effective_saturation = true;
    m.initial.liquid_pressure = -2e4;  // 20 kPa suction: S_L ~ 0.5
  }
  return m;
}

BoundarySpec fixity(const std::string& set, bool x, bool y) {
  BoundarySpec b;
  b.name = set + " fixity";
  b.kind = BoundaryKind::SolidFixity;
  b.node_set = set;
  b.fix_x = x;
  b.fix_y = y;
  return b;
}

BoundarySpec impermeable(const std::string& set) {
  BoundarySpec b;
  b.name = set + " seal";
  b.kind = BoundaryKind::LiquidFixity;
  b.side_set = set;
  return b;
}

constexpr const char* kSchemePrefix = "quad4-mohr-coulomb-";

/// The quad4-mohr-coulomb block.
Scene mohrCoulombBlock(const std::string& name) {
  Scene scene = makeBlockScene(name, ElementType::Quad4, 160, 160, PhaseModel::Saturated);
  for (auto& material : scene.materials) {
    material.solid.model = SolidModel::MohrCoulomb;
    material.solid.cohesion = 5e3;
    material.solid.friction_angle = 30 * M_PI / 180;
    material.solid.dilatancy_angle = 0;
  }
  return scene;
}

/// quad4-mohr-coulomb-<shapes>-<transfer> (BenchmarkScenes.hpp).
Scene schemeScene(const std::string& name) {
  const std::string scheme = name.substr(std::string(kSchemePrefix).size());
  const std::size_t dash = scheme.find('-');
  const std::string shapes = scheme.substr(0, dash);
  const std::string transfer = dash == std::string::npos ? "" : scheme.substr(dash + 1);
  if ((shapes != "linear" && shapes != "gimp" && shapes != "bspline") ||
      (transfer != "flip" && transfer != "apic" && transfer != "tpic"))
    throw std::invalid_argument("unknown scene '" + name + "'");
  Scene scene = mohrCoulombBlock(name);
  if (shapes != "linear") {  // the block's mesh as generateRectangle describes a grid
    scene.mesh.structured.cells[0] = scene.mesh.structured.cells[1] = 160;
    scene.mesh.structured.spacing[0] = scene.mesh.structured.spacing[1] = kCell;
    scene.mesh.shape_functions = shapes == "gimp" ? ShapeFamily::Gimp : ShapeFamily::BSpline;
  }
  scene.stage.transfer = transfer == "apic"   ? TransferScheme::Apic
                         : transfer == "tpic" ? TransferScheme::Tpic
                                              : TransferScheme::Flip;
  return scene;
}

}  // namespace

Scene makeBlockScene(const std::string& name, ElementType type, int cells, int soil_cells,
                     PhaseModel phase) {
  Scene scene;
  scene.name = name;
  scene.mesh = structuredMesh(type, cells, cells, soil_cells, soil_cells);
  const int per = type == ElementType::Quad4 ? 4 : 3;
  scene.materials = {soil(phase, per)};
  scene.points = seedMaterialPoints(scene.mesh, {SeedRequest{0, 0, per}});
  initialisePointState(scene.materials, scene.points);
  scene.stage.name = "benchmark";
  scene.stage.solver = SolverKind::Explicit;
  scene.stage.gravity = kStandardGravity;
  scene.stage.duration = 1;
  scene.stage.boundaries = {fixity("bottom", true, true), fixity("left", true, false),
                            fixity("right", true, false), impermeable("bottom"),
                            impermeable("left"),          impermeable("right")};
  // The deck's default criteria (Mieremet, consolidation) let the unsaturated block blow up
  // after ~170 steps (kinetic energy bound): there the coupled criterion (Table 4.4) governs
  // with about half the Mieremet step.
  if (phase == PhaseModel::Unsaturated)
    scene.stage.time_step.criteria = {CriterionKind::Mieremet, CriterionKind::Infiltration,
                                      CriterionKind::UnsaturatedCoupled};
  return scene;
}

std::vector<std::string> sceneNames() {
  return {"quad4-saturated", "tri3-saturated", "quad4-empty-mesh", "quad4-dry",
          "quad4-unsaturated"};
}

Scene makeScene(const std::string& name) {
  if (name == "quad4-saturated")
    return makeBlockScene(name, ElementType::Quad4, 160, 160, PhaseModel::Saturated);
  if (name == "tri3-saturated")
    return makeBlockScene(name, ElementType::Tri3, 130, 130, PhaseModel::Saturated);
  if (name == "quad4-empty-mesh")
    return makeBlockScene(name, ElementType::Quad4, 320, 160, PhaseModel::Saturated);
  if (name == "quad4-dry")
    return makeBlockScene(name, ElementType::Quad4, 160, 160, PhaseModel::Dry);
  if (name == "quad4-tiny")  // fixed cost per step: 16 points
    return makeBlockScene(name, ElementType::Quad4, 4, 2, PhaseModel::Saturated);
  if (name == "quad4-unsaturated")
    return makeBlockScene(name, ElementType::Quad4, 160, 160, PhaseModel::Unsaturated);
  if (name == "quad4-mohr-coulomb")  // the return mapping at every point (not in the list)
    return mohrCoulombBlock(name);
  if (name.rfind(kSchemePrefix, 0) == 0) return schemeScene(name);
  throw std::invalid_argument("unknown scene '" + name + "'");
}

std::vector<std::string> schemeSceneNames() {
  std::vector<std::string> names;
  for (const char* shapes : {"linear", "gimp", "bspline"})
    for (const char* transfer : {"flip", "apic", "tpic"})
      names.push_back(std::string(kSchemePrefix) + shapes + "-" + transfer);
  return names;
}

std::vector<std::string> parseSceneList(const std::string& list) {
  std::vector<std::string> scenes;
  std::stringstream words(list);
  for (std::string word; std::getline(words, word, ',');) {
    if (word == "schemes") {
      const auto schemes = schemeSceneNames();
      scenes.insert(scenes.end(), schemes.begin(), schemes.end());
    } else {
      scenes.push_back(word);
    }
  }
  return scenes;
}

void shufflePoints(MaterialPoints& points) {
  std::vector<int> order(points.count);
  for (int p = 0; p < points.count; ++p) order[p] = p;
  std::mt19937 random(12345);
  std::shuffle(order.begin(), order.end(), random);
  forEachPointField(points, [&](const char*, auto& field) {
    using FieldView = std::remove_reference_t<decltype(field)>;
    auto source = Kokkos::create_mirror(Kokkos::HostSpace(), field);
    Kokkos::deep_copy(source, field);
    auto target = Kokkos::create_mirror(Kokkos::HostSpace(), field);
    for (int p = 0; p < points.count; ++p) {
      if constexpr (FieldView::rank == 1)
        target(p) = source(order[p]);
      else
        for (std::size_t c = 0; c < field.extent(1); ++c) target(p, c) = source(order[p], c);
    }
    Kokkos::deep_copy(field, target);
  });
}

}  // namespace argine::benchmark
