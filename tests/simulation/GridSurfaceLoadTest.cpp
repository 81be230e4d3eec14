// [2Phase][Boundary] Hydraulic loads where the mesh does not follow the surface
// (`Hydraulic Loads`, physics/PointBorneLoads.hpp, doc/theory.md Sec. 5.5).
//
// A saturated bank drawn as a soil region of a 0.1 m uGIMP grid: crest at y = 0.65 m, a
// 5:7 slope to a berm at y = 0.15 m, so every surface cuts through its cells and the slope
// leaves cells holding one or two of their four points. Water stands over all of it to
// H = 2 m (total head), the settle is quasi-static, so every point's p_L should be the
// hydrostatic rho_L g (H - y), 19.6 kPa at y = 0. On the staircase of cell edges (the
// thesis' free sides) a loaded node beside a partly filled cell is carried by the few points
// near it, whose p_L rises to +79 kPa above hydrostatic (the largest total vertical stress
// in the model is 26 kPa). Passed through the points to their outer edges, the loads leave
// +10 kPa at the worst point (alone in its cell on the slope) and 2 kPa rms along the
// surface.
#include <gtest/gtest.h>

#include <Teuchos_YamlParameterListCoreHelpers.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>

#include "QuietRun.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/simulation/Simulation.hpp"

namespace argine {
namespace {

constexpr double kHead = 2.0;                      // m
constexpr double kHydrostaticBase = 9810 * kHead;  // rho_L g H at y = 0 (Pa)

std::string submergedBank(const std::string& loads) {
  return R"(argine:
  Mesh:
    Shape Functions: GIMP
    Generate:
      Type: rectangle
      Element: quad4
      Element Size (m): 0.1
      Lower Left (m): [0.0, 0.0]
      Upper Right (m): [2.0, 1.0]
      Regions:
        soil: {Vertices (m): [0.0, 0.0, 2.0, 0.0, 2.0, 0.15, 1.2, 0.15, 0.5, 0.65, 0.0, 0.65]}
  Materials:
    soil:
      Block: soil
      Points Per Element: 4
      Phase Model: unsaturated
      Porosity: 0.4
      Solid Density (kg/m3): 2700
      Mass Balance: complete
      Solid: {Model: linear elastic, Young's Modulus (Pa): 2.0e7, Poisson's Ratio: 0.3}
      Liquid: {Density (kg/m3): 1000, Bulk Modulus (Pa): 8.0e7, Viscosity (Pa s): 1.0e-3}
      Retention: {Model: linear, Slope (1/Pa): 4.0e-7, Minimum Saturation: 0.0, Maximum Saturation: 1.0}
      Conductivity: {Model: constant, Intrinsic Permeability (m2): 4.0e-11}
      Initial State: {K0: 0.5}
      Locking Mitigation: {Volumetric Strain Averaging: nodal, Intra-Element Seepage: true}
  Initialisation:
    Method: K0 procedure
    Ground Surface (m): [0.0, 0.65, 0.5, 0.65, 1.2, 0.15, 2.0, 0.15]
    Phreatic Surface (m): [0.0, 2.0, 2.0, 2.0]
  Stages:
    settle:
      Solver: quasi-static
      Duration (s): 0.3
      Gravity (m/s2): 9.81
      Local Damping: 0.7
      Hydraulic Loads: )" +
         loads + R"(
      Output Interval (s): 0.3
      Time Step: {Mode: automatic, Safety Factor: 0.5, Criteria: [cfl undrained, cfl dry, consolidation, mieremet]}
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        axis: {Type: solid fixity, Node Set: left, Direction: x}
        far side: {Type: solid fixity, Node Set: right, Direction: x}
        sealed base: {Type: impermeable, Side Set: bottom}
        sealed axis: {Type: impermeable, Side Set: left}
        water:
          Type: total head
          Zone: {Type: box, Lower Left (m): [0.05, 0.05], Upper Right (m): [2.5, 1.5]}
          Total Head (m): 2.0
  Output: {Name: bank}
)";
}

/// The bank's surface height at x (m).
double surfaceAt(double x) {
  if (x < 0.5) return 0.65;
  if (x < 1.2) return 0.65 - (x - 0.5) * 0.5 / 0.7;
  return 0.15;
}

struct Deviations {
  double largest = 0;      ///< max over points of p_L - rho_L g (H - y) (Pa)
  double farthest = 0;     ///< max over points of |p_L - rho_L g (H - y)| (Pa)
  double surface_rms = 0;  ///< rms of |p_L - rho_L g (H - y)| within 0.1 m of the surface (Pa)
};

Deviations settleBank(const std::string& loads) {
  const Deck deck = parseDeck(*Teuchos::getParametersFromYamlString(submergedBank(loads)), "");
  const auto dir = std::filesystem::path(::testing::TempDir()) /
                   (loads == "on free sides"        ? "argine_grid_surface_sides"
                    : loads == "at boundary points" ? "argine_grid_surface_points"
                                                    : "argine_grid_surface_soil");
  const RunOptions options = test::quietRunIn(dir);
  Simulation simulation(deck, options);
  simulation.run();
  const MaterialPoints& points = simulation.points();
  const auto position = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.position);
  const auto pressure =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.pressure_liquid);
  Deviations result;
  double sum = 0;
  int count = 0;
  for (int p = 0; p < points.count; ++p) {
    const double y = position(p, 1);
    const double deviation = pressure(p) - 9810 * (kHead - y);
    result.largest = std::max(result.largest, deviation);
    result.farthest = std::max(result.farthest, std::abs(deviation));
    if (surfaceAt(position(p, 0)) - y < 0.1) {
      sum += deviation * deviation;
      ++count;
    }
  }
  EXPECT_GT(count, 50);  // the surface layer: about 80 points
  result.surface_rms = std::sqrt(sum / count);
  std::printf("%s: largest %.4g Pa, farthest %.4g Pa, surface rms %.4g Pa\n", loads.c_str(),
              result.largest, result.farthest, result.surface_rms);
  return result;
}

TEST(GridSurfaceLoad, FreeSidesOverloadThePointsOfPartlyFilledCells) {
  const Deviations d = settleBank("on free sides");
  EXPECT_GT(d.largest, 2.0 * kHydrostaticBase);      // measured 4.0 x
  EXPECT_GT(d.surface_rms, 0.5 * kHydrostaticBase);  // measured 0.76 x
}

TEST(GridSurfaceLoad, BoundaryPointsKeepTheSurfaceNearHydrostatic) {
  const Deviations d = settleBank("at boundary points");
  EXPECT_LT(d.largest, 0.75 * kHydrostaticBase);     // measured 0.52 x (a point alone in its cell)
  EXPECT_LT(d.surface_rms, 0.2 * kHydrostaticBase);  // measured 0.11 x
}

TEST(GridSurfaceLoad, ThroughTheSoilKeepsTheWholeBankHydrostatic) {
  // The head's field over the points' volume (physics/HeadLoadsThroughSoil.hpp) meets the
  // points' stresses where their domains end, in full cells and in partly filled ones alike.
  const Deviations d = settleBank("through the soil");
  EXPECT_LT(d.farthest, 0.01 * kHydrostaticBase);      // measured 42 Pa (on free sides 79 kPa)
  EXPECT_LT(d.surface_rms, 0.001 * kHydrostaticBase);  // measured 4.2 Pa
}

}  // namespace
}  // namespace argine
