// [Contact][Explicit] The side walls of a quasi-2D channel (deck `side walls`): their
// width-averaged Coulomb friction 2 mu max(-sigma'_zz, 0) / W (boundary/SideWalls.hpp) on
// a block that slides between them with no gravity and no floor. Its in-plane stress is
// zero and its sigma'_zz a uniform -p, so nothing but the walls acts on it: it must slow
// down uniformly at a = 2 mu p / (rho W) along its own direction, stop at |v0| / a after
// |v0|^2 / (2 a), and then stay at rest. On linear FLIP and uGIMP APIC, across cells.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <tuple>

#include "Harness.hpp"
#include "argine/boundary/SideWalls.hpp"

namespace argine {
namespace {

using test::hostCopy;

TEST(SideWalls, ResistanceAndSlowedVelocityByHand) {
  // 2 x 0.4 x 2000 Pa / 0.1 m = 16,000 N/m^3; tension and zero stress press nothing.
  EXPECT_DOUBLE_EQ(sideWallResistance(-2000, 0.4, 0.1), 16000);
  EXPECT_EQ(sideWallResistance(500, 0.4, 0.1), 0);
  EXPECT_EQ(sideWallResistance(0, 0.4, 0.1), 0);
  EXPECT_EQ(sideWallResistance(-2000, 0, 0.1), 0);
  // |(3, 4)| = 5 loses 1: (2.4, 3.2), moving; losing 5 or more stops it exactly.
  const Real v[kDim] = {3, 4};
  Real out[kDim];
  EXPECT_FALSE(frictionSlowedVelocity(v, 1, out));
  EXPECT_DOUBLE_EQ(out[0], 2.4);
  EXPECT_DOUBLE_EQ(out[1], 3.2);
  for (const Real loss : {5.0, 6.0}) {
    EXPECT_TRUE(frictionSlowedVelocity(v, loss, out));
    EXPECT_EQ(out[0], 0);
    EXPECT_EQ(out[1], 0);
  }
  const Real rest[kDim] = {0, 0};
  EXPECT_TRUE(frictionSlowedVelocity(rest, 0, out));
}

constexpr Real kWidth = 0.1;            // channel width W (m)
constexpr Real kMu = 0.4;               // wall coefficient
constexpr Real kPress = 2000;           // -sigma'_zz (Pa)
constexpr Real kV0[kDim] = {1.2, 1.6};  // |v0| = 2 m/s: the block travels two cells

BoundarySpec sideWalls(Real mu) {
  BoundarySpec b;
  b.name = "channel";
  b.kind = BoundaryKind::SideWalls;
  b.channel_width = kWidth;
  b.friction_coefficient = mu;
  return b;
}

struct Slide {
  Real largest_speed_error = 0;  ///< max over steps and points of ||v_p| - max(|v0| - a t, 0)|
  Real largest_cross = 0;        ///< max |v_p x v0| / |v0| (direction kept)
  Real stop_distance = 0;        ///< mean displacement along v0 at the end (m)
  Real largest_sideways = 0;     ///< max displacement across v0 (m)
  Real creep_after_stop = 0;     ///< max point movement over the last 0.1 s (m)
  Real largest_szz_change = 0;   ///< max |sigma'_zz + p| at the end (Pa)
  Real deceleration = 0;         ///< the a the points' density gives (m/s^2)
  Real discrete_distance = 0;    ///< sum of dt max(|v0| - a t, 0) over the steps taken (m)
};

/// The block (cells 3..6 x 3..6 of a 20 x 12 grid of 0.1 m cells, 2 x 2 points a cell),
/// dry and elastic, sigma'_zz = sign * p, sliding at v0 between walls of coefficient mu.
Slide slide(ShapeFamily family, TransferScheme scheme, Real sign = -1, Real mu = kMu) {
  constexpr int kNx = 20, kNy = 12;
  Mesh mesh = test::rectangleMesh(kNx, kNy, 2.0, 1.2, ElementType::Quad4);
  mesh.structured.cells[0] = kNx;
  mesh.structured.cells[1] = kNy;
  mesh.structured.origin[0] = mesh.structured.origin[1] = 0;
  mesh.structured.spacing[0] = mesh.structured.spacing[1] = 0.1;
  mesh.shape_functions = family;
  MaterialPoints points = test::seedUniform(mesh, 0, [](int e) {
    const int i = e % kNx, j = e / kNx;
    return i >= 3 && i < 7 && j >= 3 && j < 7;
  });
  std::vector<MaterialSpec> materials{
      test::elasticMaterial("block", PhaseModel::Dry, 1e6, 0.3, 0.4)};
  initialisePointState(materials, points);
  {
    auto v = hostCopy(points.velocity_solid);
    auto s = hostCopy(points.stress_effective);
    for (int p = 0; p < points.count; ++p) {
      v(p, 0) = kV0[0];
      v(p, 1) = kV0[1];
      for (int c = 0; c < kStressComponents; ++c) s(p, c) = 0;
      s(p, 2) = sign * kPress;
    }
    Kokkos::deep_copy(points.velocity_solid, v);
    Kokkos::deep_copy(points.stress_effective, s);
  }
  const auto mass = hostCopy(points.mass_solid);
  const auto volume = hostCopy(points.volume);
  Slide out;
  const Real rho = mass(0) / volume(0);
  out.deceleration = sign < 0 ? 2 * mu * kPress / (rho * kWidth) : 0;
  const Real speed0 = std::hypot(kV0[0], kV0[1]);
  const Real along[kDim] = {kV0[0] / speed0, kV0[1] / speed0};

  ExplicitTwoPhaseSolver solver(mesh, points, materials);
  StageSpec stage = test::makeStage("slide", SolverKind::Explicit, 0.0, 0.0, {sideWalls(mu)},
                                    {CriterionKind::CflDry});
  stage.transfer = scheme;
  solver.beginStage(stage);
  const Real stop = out.deceleration > 0 ? speed0 / out.deceleration : 1e9;
  const Real end = (out.deceleration > 0 ? stop : 0.1) + 0.1;  // unslowed: 0.4 m, in the mesh
  Real last = 0;
  auto check = [&] {
    const auto v = hostCopy(points.velocity_solid);
    const Real expected = std::max(speed0 - out.deceleration * solver.time(), Real(0));
    // the step moves the points with the new velocity (7.13)
    out.discrete_distance += (solver.time() - last) * expected;
    last = solver.time();
    for (int p = 0; p < points.count; ++p) {
      out.largest_speed_error =
          std::max(out.largest_speed_error, std::fabs(std::hypot(v(p, 0), v(p, 1)) - expected));
      out.largest_cross =
          std::max(out.largest_cross, std::fabs(v(p, 0) * along[1] - v(p, 1) * along[0]));
    }
  };
  test::runUntil(solver, end - 0.1, check);
  const auto before = hostCopy(points.position);
  test::runUntil(solver, end, check);
  const auto x = hostCopy(points.position);
  const auto x0 = hostCopy(points.initial_position);
  const auto s = hostCopy(points.stress_effective);
  for (int p = 0; p < points.count; ++p) {
    const Real u[kDim] = {x(p, 0) - x0(p, 0), x(p, 1) - x0(p, 1)};
    out.stop_distance += (u[0] * along[0] + u[1] * along[1]) / points.count;
    out.largest_sideways =
        std::max(out.largest_sideways, std::fabs(u[0] * along[1] - u[1] * along[0]));
    out.creep_after_stop =
        std::max(out.creep_after_stop, std::hypot(x(p, 0) - before(p, 0), x(p, 1) - before(p, 1)));
    out.largest_szz_change = std::max(out.largest_szz_change, std::fabs(s(p, 2) - sign * kPress));
  }
  EXPECT_EQ(solver.diagnostics().lost_points, 0);
  return out;
}

TEST(SideWalls, OneChannelAStage) {
  const Mesh mesh = test::rectangleMesh(2, 2, 1.0, 1.0, ElementType::Quad4);
  BoundarySpec second = sideWalls(0.2);
  second.name = "channel2";
  const StageSpec stage =
      test::makeStage("slide", SolverKind::Explicit, 0.0, 0.0, {sideWalls(kMu), second});
  try {
    StageBoundaryConditions conditions(mesh, stage);
    ADD_FAILURE() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Stages/slide/Boundary Conditions/channel2");
    EXPECT_NE(std::string(error.what()).find("already given as 'channel'"), std::string::npos)
        << error.what();
  }
  const StageBoundaryConditions one(
      mesh, test::makeStage("slide", SolverKind::Explicit, 0.0, 0.0, {sideWalls(kMu)}));
  ASSERT_TRUE(one.sideWalls().has_value());
  EXPECT_EQ(one.sideWalls()->width, kWidth);
  EXPECT_EQ(one.sideWalls()->friction, kMu);
}

class SideWallSlide : public ::testing::TestWithParam<std::tuple<ShapeFamily, TransferScheme>> {};

TEST_P(SideWallSlide, BlockSlowsUniformlyAndStopsWhereCoulombSays) {
  const auto [family, scheme] = GetParam();
  const Slide s = slide(family, scheme);
  const Real speed0 = std::hypot(kV0[0], kV0[1]);
  const Real expected = speed0 * speed0 / (2 * s.deceleration);
  std::printf(
      "[ measured ] a = %.4f m/s^2: stop distance %.6f m against %.6f (%+.3f %%; the steps' "
      "%.6f), speed error "
      "%.1e m/s, sideways %.1e m, creep after the stop %.1e m, sigma_zz change %.1e Pa\n",
      s.deceleration, s.stop_distance, expected, 100 * (s.stop_distance / expected - 1),
      s.discrete_distance, s.largest_speed_error, s.largest_sideways, s.creep_after_stop,
      s.largest_szz_change);
  // Every point's speed is |v0| - a t at every step (one acceleration for the whole block:
  // R_i / M_i = 2 mu p / (rho W) at every node), then zero.
  EXPECT_LT(s.largest_speed_error, 1e-9 * speed0);
  EXPECT_LT(s.largest_cross, 1e-9 * speed0);
  // The distance of the steps taken, to round-off; it differs from v0^2 / (2 a) by O(a dt).
  EXPECT_NEAR(s.stop_distance, s.discrete_distance, 1e-9 * expected);
  EXPECT_NEAR(s.stop_distance, expected, 0.02 * expected);
  EXPECT_LT(s.largest_sideways, 1e-9);
  EXPECT_EQ(s.creep_after_stop, 0);       // stuck is at rest, not creeping
  EXPECT_LT(s.largest_szz_change, 1e-6);  // the premise: a rigid translation
}

TEST_P(SideWallSlide, WallsPressedByNothingDoNotSlowTheBlock) {
  // sigma'_zz in tension, or mu = 0: the block keeps |v0| (to round-off) for 0.4 s.
  const auto [family, scheme] = GetParam();
  for (const auto& [sign, mu] : {std::pair<Real, Real>{+1, kMu}, {-1, 0}}) {
    const Slide s = slide(family, scheme, sign, mu);
    EXPECT_LT(s.largest_speed_error, 1e-12) << "sign " << sign << " mu " << mu;
  }
}

INSTANTIATE_TEST_SUITE_P(
    Schemes, SideWallSlide,
    ::testing::Values(std::make_tuple(ShapeFamily::Linear, TransferScheme::Flip),
                      std::make_tuple(ShapeFamily::Gimp, TransferScheme::Apic),
                      std::make_tuple(ShapeFamily::BSpline, TransferScheme::Tpic)),
    [](const auto& info) {
      const ShapeFamily family = std::get<0>(info.param);
      return std::string(family == ShapeFamily::Linear ? "LinearFlip"
                         : family == ShapeFamily::Gimp ? "GimpApic"
                                                       : "BSplineTpic");
    });

}  // namespace
}  // namespace argine
