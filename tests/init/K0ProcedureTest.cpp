// K0 procedure (thesis Ch. 4 Sec. 5.1): formulas, polylines, vertical columns through the
// mesh and the point state, each against hand-computed values.
#include <gtest/gtest.h>

#include <cmath>

#include "TestMeshes.hpp"
#include "argine/core/Error.hpp"
#include "argine/core/Polyline.hpp"
#include "argine/init/K0Formulas.hpp"
#include "argine/init/K0Procedure.hpp"
#include "argine/init/VerticalColumns.hpp"
#include "argine/input/Deck.hpp"
#include "argine/physics/PointInitialisation.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/points/Seeding.hpp"

namespace argine {
namespace {

TEST(K0Formulas, HydrostaticPressureAndCap) {
  // 1000 * 10 * (3 - 1) = 20000 Pa below; 1000 * 10 * (3 - 5) = -20000 Pa above, capped at
  // -5000 Pa when s_max = 5 kPa; no cap (negative s_max) keeps -20000.
  EXPECT_DOUBLE_EQ(hydrostaticPressure(1000, 10, 3, 1, -1), 20000);
  EXPECT_DOUBLE_EQ(hydrostaticPressure(1000, 10, 3, 5, -1), -20000);
  EXPECT_DOUBLE_EQ(hydrostaticPressure(1000, 10, 3, 5, 5000), -5000);
  EXPECT_NEAR(hydrostaticPressure(1000, 10, 3, 3.2, 5000), -2000, 1e-9);
}

TEST(K0Formulas, UnitWeightAndBishop) {
  // (0.6 * 2700 + 0.4 * 0.5 * 1000) * 10 = (1620 + 200) * 10 = 18200 N/m3
  EXPECT_DOUBLE_EQ(unitWeight(0.4, 2700, 0.5, 1000, 10), 18200);
  // dry: 0.6 * 2700 * 10 = 16200
  EXPECT_DOUBLE_EQ(unitWeight(0.4, 2700, 0, 1000, 10), 16200);
  // sigma' = -50000 + 0.8 * (-10000) = -58000
  EXPECT_DOUBLE_EQ(bishopEffectiveStress(-50000, 0.8, -10000), -58000);
}

TEST(Polyline, InterpolatesAndContinuesFlat) {
  const Polyline line({{0.0, 1.0}, {2.0, 3.0}, {4.0, 3.0}}, "here");
  EXPECT_DOUBLE_EQ(line.at(1.0), 2.0);
  EXPECT_DOUBLE_EQ(line.at(3.0), 3.0);
  EXPECT_DOUBLE_EQ(line.at(-5.0), 1.0);
  EXPECT_DOUBLE_EQ(line.at(9.0), 3.0);
  EXPECT_THROW(Polyline({{0.0, 1.0}, {0.0, 2.0}}, "here"), InputError);
  EXPECT_THROW(Polyline({}, "here"), InputError);
}

/// A 2 x 4 quad grid on [0, 2] x [0, 4]: rows 0-1 block "lower", row 2 "upper", row 3 empty.
Mesh layeredMesh(ElementType type) {
  test::GridOptions o;
  o.nx = 2;
  o.ny = 4;
  o.lx = 2;
  o.ly = 4;
  o.block_names = {"lower", "upper", "air"};
  o.block = [](int, int j) { return j < 2 ? 0 : (j == 2 ? 1 : 2); };
  return test::structuredMesh(type, o);
}

MaterialSpec material(const std::string& name, const std::string& block, PhaseModel phase,
                      Real porosity, Real solid_density) {
  MaterialSpec m;
  m.name = name;
  m.block = block;
  m.phase = phase;
  m.porosity = porosity;
  m.solid_density = solid_density;
  m.solid.youngs_modulus = 1e7;
  m.solid.poisson_ratio = 0.3;
  m.conductivity.saturated_conductivity = 1e-5;
  m.liquid.bulk_modulus = 1e8;
  return m;
}

TEST(VerticalColumns, IntervalsFollowTheBlocks) {
  for (ElementType type : {ElementType::Quad4, ElementType::Tri3}) {
    const Mesh mesh = layeredMesh(type);
    std::vector<MaterialSpec> materials{material("a", "lower", PhaseModel::Dry, 0.4, 2000),
                                        material("b", "upper", PhaseModel::Dry, 0.4, 2000)};
    const VerticalColumns columns(mesh, elementMaterials(mesh, materials));
    // x = 0.3 from y = 0.5 to 10: material 0 on [0.5, 2], material 1 on [2, 3], air above.
    const auto found = columns.intervals(0.3, 0.5, 10);
    Real lower = 0, upper = 0;
    for (const auto& i : found) (i.material == 0 ? lower : upper) += i.y_high - i.y_low;
    EXPECT_NEAR(lower, 1.5, 1e-12);
    EXPECT_NEAR(upper, 1.0, 1e-12);
    // Along the shared edge x = 1 each height counts once.
    Real total = 0;
    for (const auto& i : columns.intervals(1.0, 0, 10)) total += i.y_high - i.y_low;
    EXPECT_NEAR(total, 3.0, 1e-12);
  }
}

TEST(VerticalColumns, RegionsLayerByTheirPolygonsNotByWholeElements) {
  // A rectangle with Regions: 2 x 4 cells of 1 m; block "slope" has the region
  // (0, 0), (2, 0), (0, 2) (hypotenuse x + y = 2), whose points are seeded inside the
  // polygon; its element blocks (here rows 0-1, a staircase) must not decide the layers.
  Mesh mesh = layeredMesh(ElementType::Quad4);
  mesh.blocks[0].name = "slope";
  mesh.regions.push_back({0, {{0.0, 0.0}, {2.0, 0.0}, {0.0, 2.0}}});
  const std::vector<MaterialSpec> materials{material("sand", "slope", PhaseModel::Dry, 0.4, 2000),
                                            material("b", "upper", PhaseModel::Dry, 0.4, 2000)};
  const std::vector<int> by_element = elementMaterials(mesh, materials);
  for (int e : mesh.blocks[0].elements) EXPECT_EQ(by_element[e], -1);  // not whole elements
  const VerticalColumns columns(mesh, by_element, regionMaterials(mesh, materials));
  // x = 1.5: the slope on [0, 0.5] (not [0, 2]), then nothing up to the upper block [2, 3].
  const auto found = columns.intervals(1.5, 0, 10);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0].material, 0);
  EXPECT_NEAR(found[0].y_low, 0.0, 1e-15);
  EXPECT_NEAR(found[0].y_high, 0.5, 1e-15);
  EXPECT_EQ(found[1].material, 1);
  EXPECT_NEAR(found[1].y_low, 2.0, 1e-15);
  EXPECT_NEAR(found[1].y_high, 3.0, 1e-15);
  // The K0 overburden at (1.5, 0.1) below a ground line at y = 2 counts the soil present:
  // 0.4 m of dry sand, 0.6 * 2000 * 10 * 0.4 = 4800 Pa (whole elements of rows 0-1 would
  // give 1.9 m, 22800 Pa).
  InitialisationSpec spec;
  spec.method = InitialisationSpec::Method::K0Procedure;
  spec.ground_surface = {{0.0, 2.0}, {2.0, 2.0}};
  const K0Profile profile(spec, mesh, materials, 10);
  EXPECT_NEAR(profile.totalVerticalStress(1.5, 0.1), -4800, 1e-9);
}

TEST(K0Profile, DryOverSaturatedWithRiverAboveGround) {
  // Lower block saturated (n = 0.4, rho_S = 2700), upper block dry (n = 0.5, rho_S = 2600),
  // ground surface at y = 3, g = 10. Phreatic surface at y = 1.5 (in the lower layer).
  const Mesh mesh = layeredMesh(ElementType::Quad4);
  std::vector<MaterialSpec> materials{
      material("foundation", "lower", PhaseModel::Saturated, 0.4, 2700),
      material("dike", "upper", PhaseModel::Dry, 0.5, 2600)};
  materials[0].initial.earth_pressure_coefficient = 0.5;
  InitialisationSpec spec;
  spec.method = InitialisationSpec::Method::K0Procedure;
  spec.ground_surface = {{0.0, 3.0}, {2.0, 3.0}};
  spec.phreatic_surface = {{0.0, 1.5}, {2.0, 1.5}};
  const K0Profile profile(spec, mesh, materials, 10);
  // Point at (0.5, 0.5) in the saturated layer:
  //   p_L = 1000 * 10 * (1.5 - 0.5) = 10000 Pa
  //   overburden: dry 1 m: 0.5 * 2600 * 10 = 13000; saturated 1.5 m (S_L = 1 also above the
  //   phreatic surface for a saturated material): (0.6 * 2700 + 0.4 * 1000) * 10 * 1.5
  //   = 20200 * 1.5 = 30300; sigma_yy = -43300; sigma'_yy = -43300 + 10000 = -33300.
  K0State s = profile.state(0, 0.5, 0.5);
  EXPECT_NEAR(s.liquid_pressure, 10000, 1e-9);
  EXPECT_NEAR(s.saturation, 1.0, 1e-15);
  EXPECT_NEAR(s.total_vertical_stress, -43300, 1e-8);
  EXPECT_NEAR(s.effective_vertical_stress, -33300, 1e-8);
  EXPECT_DOUBLE_EQ(s.earth_pressure_coefficient, 0.5);
  // Point at (0.5, 2.5) in the dry layer: sigma = -0.5 * 13000 = -6500 = sigma'.
  s = profile.state(1, 0.5, 2.5);
  EXPECT_NEAR(s.total_vertical_stress, -6500, 1e-9);
  EXPECT_NEAR(s.effective_vertical_stress, -6500, 1e-9);
  EXPECT_DOUBLE_EQ(s.liquid_pressure, 0);

  // A river: phreatic surface at y = 5, 2 m above the ground. The free water adds
  // 1000 * 10 * 2 = 20000 Pa: at (0.5, 0.5): sigma = -63300, p_L = 45000, sigma' = -18300.
  spec.phreatic_surface = {{0.0, 5.0}, {2.0, 5.0}};
  const K0Profile river(spec, mesh, materials, 10);
  s = river.state(0, 0.5, 0.5);
  EXPECT_NEAR(s.total_vertical_stress, -63300, 1e-8);
  EXPECT_NEAR(s.liquid_pressure, 45000, 1e-9);
  EXPECT_NEAR(s.effective_vertical_stress, -18300, 1e-8);
}

TEST(K0Profile, SlopingGroundStartsTheIntegralAtTheSurface) {
  // Ground from (0, 1) to (2, 3): at x = 0.5 the ground is at y = 1.5. One dry material
  // filling both blocks' rows 0-2 (n = 0.5, rho_S = 2000, g = 10): gamma = 10000 N/m3.
  // At (0.5, 0.25): sigma = -10000 * (1.5 - 0.25) = -12500 (the mesh above the ground line
  // does not count).
  const Mesh mesh = layeredMesh(ElementType::Tri3);
  std::vector<MaterialSpec> materials{material("a", "lower", PhaseModel::Dry, 0.5, 2000),
                                      material("b", "upper", PhaseModel::Dry, 0.5, 2000)};
  InitialisationSpec spec;
  spec.ground_surface = {{0.0, 1.0}, {2.0, 3.0}};
  const K0Profile profile(spec, mesh, materials, 10);
  EXPECT_NEAR(profile.totalVerticalStress(0.5, 0.25), -12500, 1e-8);
  // At x = 1.5 the ground is at 2.5: from y = 0.25, 2.25 m: -22500.
  EXPECT_NEAR(profile.totalVerticalStress(1.5, 0.25), -22500, 1e-8);
}

TEST(K0Profile, UnsaturatedLayerWithSuctionCap) {
  // One unsaturated layer on [0, 2] (block "lower"), linear SWRC S_L = 1 - 1e-5 s (so the
  // integral is exact by hand), phreatic at y = 0.5, g = 10, rho_L = 1000, n = 0.4,
  // rho_S = 2500, cap s_max = 10000 Pa (reached 1 m above the phreatic surface, y = 1.5).
  //   unit weight: (0.6 * 2500 + 0.4 * S_L * 1000) * 10 = 15000 + 4000 S_L
  //   y in [1.5, 2]: s = 10^4, S_L = 0.9: gamma = 18600, over 0.5 m: 9300
  //   y in [0.5, 1.5]: s = 10^4 (y - 0.5), S_L = 1 - 0.1 (y - 0.5): gamma = 19000 - 400 (y-0.5),
  //       integral = 19000 - 200 = 18800
  //   y in [0, 0.5]: S_L = 1, gamma = 19000, down to y = 0.25: 4750
  // Point at (0.5, 0.25): sigma = -(9300 + 18800 + 4750) = -32850, p_L = 2500,
  // sigma' = -32850 + 2500 = -30350.
  // Point at (0.5, 1.0): p_L = -5000, S_L = 0.95, sigma = -(9300 + int_1^1.5) =
  //   -(9300 + 0.5 * 19000 - 400 * (1^2 - 0.5^2) / 2) = -(9300 + 9500 - 150) = -18650,
  //   sigma' = -18650 + 0.95 * (-5000) = -23400.
  const Mesh mesh = layeredMesh(ElementType::Quad4);
  MaterialSpec m = material("silt", "lower", PhaseModel::Unsaturated, 0.4, 2500);
  m.retention.model = RetentionModel::Linear;
  m.retention.linear_slope = 1e-5;
  m.retention.saturation_min = 0;
  m.retention.saturation_max = 1;
  InitialisationSpec spec;
  spec.ground_surface = {{0.0, 2.0}};
  spec.phreatic_surface = {{0.0, 0.5}};
  spec.max_suction = 10000;
  const K0Profile profile(spec, mesh, {m}, 10);
  K0State s = profile.state(0, 0.5, 0.25);
  EXPECT_NEAR(s.liquid_pressure, 2500, 1e-9);
  EXPECT_NEAR(s.total_vertical_stress, -32850, 1e-7);
  EXPECT_NEAR(s.effective_vertical_stress, -30350, 1e-7);
  s = profile.state(0, 0.5, 1.0);
  EXPECT_NEAR(s.liquid_pressure, -5000, 1e-9);
  EXPECT_NEAR(s.saturation, 0.95, 1e-12);
  EXPECT_NEAR(s.total_vertical_stress, -18650, 1e-7);
  EXPECT_NEAR(s.effective_vertical_stress, -23400, 1e-7);
}

TEST(K0Procedure, SetsThePointState) {
  // Saturated layer "lower" ([0,2] x [0,2]), ground and water at y = 2, g = 10, K0 = 0.5,
  // n = 0.4, rho_S = 2700: gamma_sat = 20200, p_L = 10^4 (2 - y), sigma' = -10200 (2 - y).
  const Mesh mesh = layeredMesh(ElementType::Quad4);
  MaterialSpec m = material("sand", "lower", PhaseModel::Saturated, 0.4, 2700);
  m.initial.earth_pressure_coefficient = 0.5;
  m.points_per_element = 4;
  std::vector<MaterialSpec> materials{m};
  MaterialPoints points = seedMaterialPoints(mesh, {SeedRequest{0, 0, 4}});
  initialisePointState(materials, points);
  InitialisationSpec spec;
  spec.ground_surface = {{0.0, 2.0}};
  spec.phreatic_surface = {{0.0, 2.0}};
  applyK0Procedure(K0Profile(spec, mesh, materials, 10), points);
  auto position = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.position);
  auto stress = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.stress_effective);
  auto pressure = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.pressure_liquid);
  auto mass = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.mass_liquid);
  auto volume = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.volume);
  ASSERT_GT(points.count, 0);
  for (int p = 0; p < points.count; ++p) {
    const Real depth = 2 - position(p, 1);
    EXPECT_NEAR(pressure(p), 1e4 * depth, 1e-8);
    EXPECT_NEAR(stress(p, YY), -10200 * depth, 1e-8);
    EXPECT_NEAR(stress(p, XX), -5100 * depth, 1e-8);
    EXPECT_NEAR(stress(p, ZZ), -5100 * depth, 1e-8);
    EXPECT_EQ(stress(p, XY), 0);
    // M_L = n S_L rho_L0 exp(p_L/K_L) V
    EXPECT_NEAR(mass(p), 0.4 * 1000 * std::exp(1e4 * depth / 1e8) * volume(p), 1e-9 * mass(p));
  }
}

}  // namespace
}  // namespace argine
