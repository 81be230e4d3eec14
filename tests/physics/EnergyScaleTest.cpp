// The energy scale of the instability bound (StabilityCheck.hpp: pointEnergies, energyScale,
// inflowEnergyPerMass) against hand-computed values, and the explicit solver's stop at
// 1 x that scale (and not below it).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "Harness.hpp"
#include "argine/core/Error.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/StabilityCheck.hpp"

namespace argine {
namespace {

using test::hostCopy;
using test::makeStage;

/// Sets point p's state on the host copies.
struct PointState {
  Real x, y, mass_solid, mass_liquid;
  int element;
  Real vs[2], vl[2];
  Real stress_xx, volume;
};

TEST(EnergyScale, PointEnergiesByHand) {
  // Four points of a 1 m x 4 m mesh from y = -0.5 (the datum) to y = 3.5, g = 10 m/s^2:
  //   p0 at y = 2.5, inside:          (10 + 2) kg x 10 x 3.0 m = 360 J/m
  //   p1 at y = 0.5, inside:          (5 + 1)  kg x 10 x 1.0 m =  60 J/m
  //   p2 at y = -1.0, below the datum (element kept >= 0): no potential energy
  //   p3 at y = 5.0, lost (element -1, a removed point): no potential energy
  // potential 420 J/m (the old scale's weight x g would count all 30 kg).
  // Kinetic: p0 v_S = (1, 0): 1/2 10 1 = 5; p1 v_L = (0, 2): 1/2 1 4 = 2 -> 7 J/m.
  // Stored: p0 sigma'_xx = 1e4 Pa, V = 0.5 m^2, E = 1e7: 0.5 x 1e8 / 2e7 = 2.5 J/m (p_L = 0).
  const Mesh mesh = test::rectangleMesh(1, 4, 1.0, 4.0, ElementType::Quad4, 0.0, -0.5);
  MaterialPoints points = test::seedUniform(mesh);
  std::vector<MaterialSpec> materials{
      test::elasticMaterial("sand", PhaseModel::Saturated, 1e7, 0.3, 0.4)};
  initialisePointState(materials, points);
  ASSERT_EQ(points.count, 16);
  const PointState state[4] = {
      {0.5, 2.5, 10, 2, 3, {1, 0}, {0, 0}, 1e4, 0.5},
      {0.5, 0.5, 5, 1, 1, {0, 0}, {0, 2}, 0, 0.5},
      {0.5, -1.0, 7, 3, 0, {0, 0}, {0, 0}, 0, 0.5},
      {0.5, 5.0, 2, 0, -1, {0, 0}, {0, 0}, 0, 0.5},
  };
  auto x = hostCopy(points.position);
  auto ms = hostCopy(points.mass_solid);
  auto ml = hostCopy(points.mass_liquid);
  auto element = hostCopy(points.element);
  auto vs = hostCopy(points.velocity_solid);
  auto vl = hostCopy(points.velocity_liquid);
  auto stress = hostCopy(points.stress_effective);
  auto pressure = hostCopy(points.pressure_liquid);
  auto volume = hostCopy(points.volume);
  for (int p = 0; p < points.count; ++p) {  // the other 12 points: no mass, at rest
    const PointState s = p < 4 ? state[p] : PointState{0.5, 1.0, 0, 0, 1, {0, 0}, {0, 0}, 0, 0.5};
    x(p, 0) = s.x;
    x(p, 1) = s.y;
    ms(p) = s.mass_solid;
    ml(p) = s.mass_liquid;
    element(p) = s.element;
    for (int d = 0; d < kDim; ++d) {
      vs(p, d) = s.vs[d];
      vl(p, d) = s.vl[d];
    }
    for (int c = 0; c < kStressComponents; ++c) stress(p, c) = 0;
    stress(p, XX) = s.stress_xx;
    pressure(p) = 0;
    volume(p) = s.volume;
  }
  Kokkos::deep_copy(points.position, x);
  Kokkos::deep_copy(points.mass_solid, ms);
  Kokkos::deep_copy(points.mass_liquid, ml);
  Kokkos::deep_copy(points.element, element);
  Kokkos::deep_copy(points.velocity_solid, vs);
  Kokkos::deep_copy(points.velocity_liquid, vl);
  Kokkos::deep_copy(points.stress_effective, stress);
  Kokkos::deep_copy(points.pressure_liquid, pressure);
  Kokkos::deep_copy(points.volume, volume);

  const MaterialTable table(materials);
  const PointEnergies e = pointEnergies(points, table, 10.0, -0.5);
  EXPECT_NEAR(e.potential, 420.0, 1e-12);
  EXPECT_NEAR(e.kinetic, 7.0, 1e-12);
  EXPECT_NEAR(e.stored, 2.5, 1e-12);
  // The scale: + loads 100 N/m x extent 10 m + inflow 3 J/m.
  EXPECT_NEAR(energyScale(e, 100.0, 10.0, 3.0), 420.0 + 7.0 + 2.5 + 1000.0 + 3.0, 1e-10);
  // Without gravity nothing falls: no potential energy.
  EXPECT_EQ(pointEnergies(points, table, 0.0, -0.5).potential, 0.0);
}

TEST(EnergyScale, InflowEnergyPerKilogramByHand) {
  // g = 10, mesh from y = -0.5 (datum) to 3.2 (top): entering at the top, 10 x 3.7 = 37 J/kg.
  const Real g = 10, top = 3.2, datum = -0.5, rho = 1000;
  // Total head H = 4 m above the top: g (H - datum) = 45 J/kg.
  EXPECT_DOUBLE_EQ(inflowEnergyPerMass(BoundaryKind::TotalHead, 4.0, 0, rho, g, top, datum), 45.0);
  // H = 2 m below the top: the top governs (37); a constant 2 kPa above the level adds 2 J/kg.
  EXPECT_DOUBLE_EQ(inflowEnergyPerMass(BoundaryKind::TotalHead, 2.0, 0, rho, g, top, datum), 37.0);
  EXPECT_DOUBLE_EQ(inflowEnergyPerMass(BoundaryKind::TotalHead, 2.0, 2000, rho, g, top, datum),
                   39.0);
  // A pressure series adds its positive pressure's work p / rho_L (5 kPa: 5 J/kg), not a suction.
  EXPECT_DOUBLE_EQ(inflowEnergyPerMass(BoundaryKind::PressureSeries, 5000, 0, rho, g, top, datum),
                   42.0);
  EXPECT_DOUBLE_EQ(inflowEnergyPerMass(BoundaryKind::PressureSeries, -3000, 0, rho, g, top, datum),
                   37.0);
  // Rain and seepage faces: the top of the mesh.
  EXPECT_DOUBLE_EQ(inflowEnergyPerMass(BoundaryKind::Infiltration, 1e-4, 0, rho, g, top, datum),
                   37.0);
  EXPECT_DOUBLE_EQ(inflowEnergyPerMass(BoundaryKind::SeepageFace, 0, 0, rho, g, top, datum), 37.0);
}

/// A free saturated 1 m x 1 m body resting in the middle of a 3 m x 3 m mesh (y from 1 to 2
/// m), no boundary conditions, g = 9.81, no initial stress: the stage's energy scale is the
/// potential energy above the mesh's bottom, M g 1.5 m with M = 0.6 x 2650 + 0.4 x 1000 =
/// 1990 kg/m (the old scale, 10 x M g x the mesh diagonal 4.24 m, was 28 times higher).
struct FreeBody {
  Mesh mesh = test::rectangleMesh(6, 6, 3.0, 3.0, ElementType::Quad4);
  MaterialPoints points;
  std::vector<MaterialSpec> materials{
      test::elasticMaterial("sand", PhaseModel::Saturated, 1e7, 0.3, 0.4)};
  FreeBody() {
    points = test::seedUniform(mesh, 0, [](int e) {
      const int i = e % 6, j = e / 6;
      return i >= 2 && i < 4 && j >= 2 && j < 4;
    });
    initialisePointState(materials, points);
  }
  /// Both phases of every point move at (v, 0): kinetic energy 1/2 M v^2.
  void setHorizontalVelocity(Real v) {
    for (auto* view : {&points.velocity_solid, &points.velocity_liquid}) {
      Kokkos::deep_copy(Kokkos::subview(*view, Kokkos::ALL, 0), v);
      Kokkos::deep_copy(Kokkos::subview(*view, Kokkos::ALL, 1), 0.0);
    }
  }
};

constexpr Real kBodyMass = 0.6 * 2650 + 0.4 * 1000;
constexpr Real kBodyScale = kBodyMass * 9.81 * 1.5;

TEST(EnergyScale, StageScaleOfAFreeBodyIsItsPotentialEnergyAboveTheMeshBottom) {
  FreeBody body;
  ExplicitTwoPhaseSolver solver(body.mesh, body.points, body.materials);
  solver.beginStage(makeStage("s", SolverKind::Explicit, 9.81, 0.0, {}));
  EXPECT_NEAR(solver.stageEnergyScale(), kBodyScale, 1e-9 * kBodyScale);
}

TEST(EnergyScale, GuardStopsAtOneTimesTheScaleAndNotBelow) {
  // Kinetic energy given to the body after the stage began (so not part of the scale): a
  // uniform horizontal velocity, which one step keeps (a rigid translation: no strain) up to
  // the gravity's 1/2 M (g dt)^2 ~ 1e-7 of it.
  auto speedFor = [](Real ratio) { return std::sqrt(2 * ratio * kBodyScale / kBodyMass); };
  {
    FreeBody body;
    ExplicitTwoPhaseSolver solver(body.mesh, body.points, body.materials);
    solver.beginStage(makeStage("s", SolverKind::Explicit, 9.81, 0.0, {}));
    body.setHorizontalVelocity(speedFor(0.98));  // 98 % of the scale: goes on
    EXPECT_NO_THROW(solver.step(solver.chooseTimeStep().time_step));
    const Real kinetic =
        solver.diagnostics().kinetic_energy_solid + solver.diagnostics().kinetic_energy_liquid;
    EXPECT_NEAR(kinetic, 0.98 * kBodyScale, 1e-4 * kBodyScale);
    EXPECT_NO_THROW(solver.step(solver.chooseTimeStep().time_step));
  }
  {
    FreeBody body;
    ExplicitTwoPhaseSolver solver(body.mesh, body.points, body.materials);
    solver.beginStage(makeStage("s", SolverKind::Explicit, 9.81, 0.0, {}));
    body.setHorizontalVelocity(speedFor(1.02));  // 102 %: more than the stage can release
    const std::string message =
        test::runErrorMessage([&] { solver.step(solver.chooseTimeStep().time_step); });
    EXPECT_NE(message.find("unstable at t = "), std::string::npos) << message;
    EXPECT_NE(message.find("exceeds 1 x the stage's energy scale 29282"), std::string::npos)
        << message;
    EXPECT_NE(message.find("potential 29282"), std::string::npos) << message;
  }
}

}  // namespace
}  // namespace argine
