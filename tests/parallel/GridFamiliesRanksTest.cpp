// The explicit step on the grid shape families (GIMP, B-spline; FLIP and APIC) over all ranks
// of MPI_COMM_WORLD gives the one-rank answer: to round-off with plain sums, bit for bit with
// reproducible sums. A point there reaches the nodes of its cell's neighbours, which may
// belong to another rank (RankDecomposition's footprints, mesh/ElementFootprint.hpp). The
// scenes move points across the rank border. Run on 2 ranks by parallel_two_ranks.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <string>
#include <tuple>
#include <vector>

#include "../physics/Harness.hpp"
#include "RanksHarness.hpp"
#include "argine/meshio/MeshGenerators.hpp"
#include "argine/points/Seeding.hpp"

namespace argine {
namespace {

using Scene = test::RanksScene;

/// The transfers of `scene` on `family` over its rectangle mesh (as generateRectangle sets
/// it), with `scheme` in every stage.
void onGrid(Scene& scene, int nx, int ny, Real width, Real height, ShapeFamily family,
            TransferScheme scheme) {
  scene.mesh.structured.cells[0] = nx;
  scene.mesh.structured.cells[1] = ny;
  scene.mesh.structured.spacing[0] = width / nx;
  scene.mesh.structured.spacing[1] = height / ny;
  scene.mesh.shape_functions = family;
  for (StageSpec& stage : scene.stages) stage.transfer = scheme;
}

/// An elastic block of 4 x 4 cells (0.5 m) on a smooth floor (rollers) sliding to the right
/// at 1 m/s under gravity through a 16 x 6 grid of 0.125 m cells, its right face on the cut
/// of the two ranks' halves (equal weights): within the steps it crosses three cells into
/// the other rank while it settles and spreads. Dry, or saturated with a soft liquid (K_L =
/// 2.2 MPa: a long stable step).
Scene slidingBlock(ShapeFamily family, TransferScheme scheme, PhaseModel phase) {
  Scene scene;
  scene.mesh = test::rectangleMesh(16, 6, 2.0, 0.75, ElementType::Quad4);
  scene.points = test::seedUniform(scene.mesh, 0, [](int e) {
    const int i = e % 16, j = e / 16;
    return i >= 4 && i < 8 && j < 4;
  });
  scene.materials = {test::elasticMaterial("soil", phase, 5e6, 0.3, 0.4, 1e-2, 2.2e6)};
  initialisePointState(scene.materials, scene.points);
  for (auto v : {scene.points.velocity_solid, scene.points.velocity_liquid})
    Kokkos::deep_copy(Kokkos::subview(v, Kokkos::ALL, 0), 1.0);
  scene.stages = {test::makeStage("slide", SolverKind::Explicit, kStandardGravity, 0.0,
                                  {test::solidFixity("floor", "bottom", false, true)})};
  scene.steps_per_stage = 400;
  scene.weights.assign(scene.mesh.numElements(), 1.0);
  // The soft liquid carries 70-900 Pa of the ~1e4 Pa of the weight (rho g H): its round-off
  // is measured on the stresses' scale (p_L's own magnifies it to 1e-10).
  scene.pressure_scale = 1e4;
  onGrid(scene, 16, 6, 2.0, 0.75, family, scheme);
  return scene;
}

/// The saturated Mohr-Coulomb slope of DistributedSolverTest (c' = 0, phi' = 25 deg, a free
/// face one column left of the cut, rough base) slumping into the other rank's elements.
Scene slumpingSlope(ShapeFamily family, TransferScheme scheme) {
  Scene scene = test::slumpingSlope(0.0);
  onGrid(scene, 16, 6, 2.0, 0.75, family, scheme);
  return scene;
}

/// The saturated Mohr-Coulomb block of the benchmarks' per-scheme scenes, built as
/// verification/benchmark/BenchmarkScenes.cpp builds quad4-mohr-coulomb-<shapes>-<transfer>
/// (the same bits): 160 x 160 cells of 0.1 m, 2 x 2 points each, c' = 5 kPa, phi' = 30 deg,
/// psi = 0, settling under gravity on a fixed, impermeable base between impermeable rollers,
/// the deck's default time step. The two ranks' halves meet on its symmetry line x = 8 m,
/// where the x sums at the nodes cancel to round-off (terms of 1e2 N, sums of 1e-8 N).
Scene mohrCoulombBlock(ShapeFamily family, TransferScheme scheme, int steps) {
  constexpr int kCells = 160;
  constexpr Real kCell = 0.1;
  std::vector<std::array<Real, 2>> nodes;
  for (int j = 0; j <= kCells; ++j)
    for (int i = 0; i <= kCells; ++i) nodes.push_back({i * kCell, j * kCell});
  std::vector<std::array<int, 4>> cells;
  for (int j = 0; j < kCells; ++j)
    for (int i = 0; i < kCells; ++i) {
      const int a = j * (kCells + 1) + i;
      cells.push_back({a, a + 1, a + kCells + 2, a + kCells + 1});
    }
  Scene scene;
  scene.mesh =
      assembleMesh(ElementType::Quad4, nodes, cells, std::vector<int>(cells.size(), 0), {"soil"});
  addBoxSideSets(scene.mesh, {0.0, 0.0}, {kCells * kCell, kCells * kCell});
  scene.points = seedMaterialPoints(scene.mesh, {SeedRequest{0, 0, 4}});
  MaterialSpec soil = test::elasticMaterial("soil", PhaseModel::Saturated, 1e7, 0.3, 0.4);
  soil.points_per_element = 4;
  soil.solid.model = SolidModel::MohrCoulomb;
  soil.solid.cohesion = 5e3;
  soil.solid.friction_angle = 30 * M_PI / 180;
  soil.solid.dilatancy_angle = 0;
  scene.materials = {soil};
  initialisePointState(scene.materials, scene.points);
  StageSpec settle;
  settle.name = "settle";
  settle.solver = SolverKind::Explicit;
  settle.gravity = kStandardGravity;
  settle.duration = 1;
  settle.boundaries = {test::solidFixity("base", "bottom", true, true),
                       test::solidFixity("left", "left", true, false),
                       test::solidFixity("right", "right", true, false),
                       test::impermeable("base seal", "bottom"),
                       test::impermeable("left seal", "left"),
                       test::impermeable("right seal", "right")};
  scene.stages = {settle};
  scene.steps_per_stage = steps;
  onGrid(scene, kCells, kCells, kCells * kCell, kCells * kCell, family, scheme);
  return scene;
}

// Plain sums: the partial sums of the ranks at the shared nodes are added in another order
// than one rank's running sum. Measured on 2 ranks (printed): at most 3e-13 (stresses; p_L
// of the saturated block 1.3e-10 of its own largest value, 1e-12 of the stresses' scale).
constexpr Real kRoundOff = 1e-11;

class GridFamiliesRanks : public ::testing::TestWithParam<std::tuple<ShapeFamily, TransferScheme>> {
};

TEST_P(GridFamiliesRanks, DryBlockSlidingAcrossTheRankBorderMatchesOneRank) {
  const auto [family, scheme] = GetParam();
  test::expectSameAsOneRankWithMigration(slidingBlock(family, scheme, PhaseModel::Dry), kRoundOff);
}

TEST_P(GridFamiliesRanks, SaturatedBlockSlidingAcrossTheRankBorderMatchesOneRank) {
  const auto [family, scheme] = GetParam();
  test::expectSameAsOneRankWithMigration(slidingBlock(family, scheme, PhaseModel::Saturated),
                                         kRoundOff);
}

TEST_P(GridFamiliesRanks, SlumpingSlopeMatchesOneRank) {
  const auto [family, scheme] = GetParam();
  test::expectSameAsOneRankWithMigration(slumpingSlope(family, scheme), kRoundOff);
}

TEST_P(GridFamiliesRanks, ReproducibleSumsEqualOneRankBitForBit) {
  const auto [family, scheme] = GetParam();
  for (const PhaseModel phase : {PhaseModel::Dry, PhaseModel::Saturated}) {
    Scene scene = slidingBlock(family, scheme, phase);
    scene.reproducible_sums = true;
    test::expectSameAsOneRankWithMigration(scene, 0.0);
  }
  Scene slope = slumpingSlope(family, scheme);
  slope.reproducible_sums = true;
  test::expectSameAsOneRankWithMigration(slope, 0.0);
}

// The run of benchmark_schemes_two_ranks (2 warm-up steps and 20) on uGIMP + APIC with
// reproducible sums. With the TwoSum pairs of 8761221 the mixture force in x at node
// (80, 2) of step 14 (36 terms up to 144 N, 6.42e-8 N in all) lay 4.9e-30 N from the midpoint
// between two doubles, and one rank's pair and two ranks' merged pairs rounded it to either
// side: 19 points differed after step 14 (the benchmark's fingerprints df5b491ea201bab7 and
// 3e64d39a1cb893bb). The uGIMP weights of these points are dyadic, so such near-ties, broken
// only by round-off terms of 1e-35 to 1e-28 that a pair's low part drops, are common.
TEST(GridFamiliesRanksBlock, GimpApicMohrCoulombBlockEqualsOneRankBitForBit) {
  Scene block = mohrCoulombBlock(ShapeFamily::Gimp, TransferScheme::Apic, 22);
  block.reproducible_sums = true;
  test::expectSameAsOneRank(block, 0.0);
}

// XPIC's round trips (XpicFilter.hpp) complete their momenta over the ranks as the remap
// does: the sliding blocks, dry and saturated, cross the rank border with the one-rank bits
// (reproducible sums), and so does the slumping slope, whose velocities vary across the
// shared nodes (the filter's work); its filtered slump moves no point across the border
// within the harness' steps, so it is compared without migration. The binomial series of
// order 2 and Chebyshev's of order 5 (its iteration's nodal combinations on both ranks).
TEST(GridFamiliesRanksXpic, SlidingBlocksAndSlumpingSlopeEqualOneRankBitForBit) {
  for (const XpicPolynomial polynomial : {XpicPolynomial{2, 0.0}, XpicPolynomial{5, 0.1}}) {
    SCOPED_TRACE(polynomial.lower_eigenvalue > 0 ? "Chebyshev XPIC(5)" : "XPIC(2)");
    const auto withPolynomial = [&](Scene scene) {
      for (StageSpec& stage : scene.stages) stage.xpic = polynomial;
      scene.reproducible_sums = true;
      return scene;
    };
    for (const ShapeFamily family : {ShapeFamily::Gimp, ShapeFamily::BSpline}) {
      SCOPED_TRACE(family == ShapeFamily::Gimp ? "GIMP" : "B-spline");
      for (const PhaseModel phase : {PhaseModel::Dry, PhaseModel::Saturated})
        test::expectSameAsOneRankWithMigration(
            withPolynomial(slidingBlock(family, TransferScheme::Xpic, phase)), 0.0);
      test::expectSameAsOneRank(withPolynomial(slumpingSlope(family, TransferScheme::Xpic)), 0.0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(
    Families, GridFamiliesRanks,
    ::testing::Combine(::testing::Values(ShapeFamily::Gimp, ShapeFamily::BSpline),
                       ::testing::Values(TransferScheme::Flip, TransferScheme::Apic)),
    [](const auto& info) {
      const ShapeFamily family = std::get<0>(info.param);
      const TransferScheme scheme = std::get<1>(info.param);
      return std::string(family == ShapeFamily::Gimp ? "Gimp" : "BSpline") +
             (scheme == TransferScheme::Apic ? "Apic" : "Flip");
    });

}  // namespace
}  // namespace argine
