// [Boundary] Resolution of a stage's conditions against the mesh, nodal loads, constraints.
#include <gtest/gtest.h>

#include "../transfer/TestScenes.hpp"
#include "argine/boundary/BoundaryConditions.hpp"
#include "argine/boundary/HydraulicAlgebra.hpp"
#include "argine/core/Error.hpp"

namespace argine {
namespace {

using test::hostCopy;

StageSpec stageWith(std::vector<BoundarySpec> boundaries) {
  StageSpec stage;
  stage.name = "flood";
  stage.boundaries = std::move(boundaries);
  return stage;
}

/// Runs the loads of `conditions` on a grid where every node carries mass.
void loadsOn(const Mesh& mesh, const StageBoundaryConditions& conditions,
             Kokkos::View<Real* [kDim], MemSpace>& mixture,
             Kokkos::View<Real* [kDim], MemSpace>& liquid) {
  Kokkos::View<Real*, MemSpace> mass("mass", mesh.numNodes());
  Kokkos::deep_copy(mass, 1.0);
  mixture = Kokkos::View<Real* [kDim], MemSpace>("mixture", mesh.numNodes());
  liquid = Kokkos::View<Real* [kDim], MemSpace>("liquid", mesh.numNodes());
  conditions.addNodalForces(0.0, mass, mixture, liquid);
}

TEST(StageBoundaryConditions, MissingSetsAreInputErrorsNamingTheCondition) {
  const Mesh mesh = test::rectangleMesh(2, 1, 2.0, 1.0, ElementType::Quad4);
  try {
    StageBoundaryConditions(mesh, stageWith({test::solidFixity("base", "floor", false, true)}));
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Stages/flood/Boundary Conditions/base");
    EXPECT_NE(std::string(error.what()).find("node set 'floor' is not in the mesh"),
              std::string::npos);
    EXPECT_NE(std::string(error.what()).find("left, right, bottom, top"), std::string::npos);
  }
  try {
    StageBoundaryConditions(mesh, stageWith({test::traction("load", "crest", 0, -1)}));
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Stages/flood/Boundary Conditions/load");
    EXPECT_NE(std::string(error.what()).find("side set 'crest'"), std::string::npos);
  }
  EXPECT_THROW(
      StageBoundaryConditions(mesh, stageWith({test::solidFixity("base", "bottom", false, false)})),
      InputError);  // a fixity without a direction
}

TEST(StageBoundaryConditions, TractionIsIntegratedWithEdgeShapeFunctions) {
  // Top of a 2 x 1 mesh of 1 m elements: two sides of L = 1 m. Each end node of a side gets
  // t L / 2: corners (nodes 3, 5) 0.5 t, the middle node (4) t; the total is t x 2 m.
  const Mesh mesh = test::rectangleMesh(2, 1, 2.0, 1.0, ElementType::Quad4);
  const StageBoundaryConditions conditions(mesh,
                                           stageWith({test::traction("load", "top", 300.0, -1e4)}));
  Kokkos::View<Real*[kDim], MemSpace> mixture, liquid;
  loadsOn(mesh, conditions, mixture, liquid);
  const auto f = hostCopy(mixture), fl = hostCopy(liquid);
  EXPECT_DOUBLE_EQ(f(3, 1), -5e3);
  EXPECT_DOUBLE_EQ(f(4, 1), -1e4);
  EXPECT_DOUBLE_EQ(f(5, 1), -5e3);
  EXPECT_DOUBLE_EQ(f(4, 0), 300.0);
  for (int i = 0; i < 3; ++i) EXPECT_EQ(f(i, 1), 0.0);   // bottom untouched
  for (int i = 0; i < 6; ++i) EXPECT_EQ(fl(i, 1), 0.0);  // a traction loads the mixture only
  EXPECT_DOUBLE_EQ(conditions.totalLoadMagnitude(),
                   std::hypot(150.0, 5e3) * 2 + std::hypot(300.0, 1e4));
}

TEST(StageBoundaryConditions, LiquidPressureLoadsLiquidAndMixture) {
  // p^ = 2e4 Pa on the right side (outward normal +x) of a 1 x 2 mesh of 1 m elements:
  // -p^ n L / 2 per side end: nodes 1 and 5 get -1e4, node 3 gets -2e4 (x), on both phases.
  // On the top (normal +y) of a Tri3 mesh it pushes down.
  const Mesh mesh = test::rectangleMesh(1, 2, 1.0, 2.0, ElementType::Quad4);
  const StageBoundaryConditions conditions(
      mesh, stageWith({test::liquidPressure("river", "right", 2e4)}));
  Kokkos::View<Real*[kDim], MemSpace> mixture, liquid;
  loadsOn(mesh, conditions, mixture, liquid);
  const auto f = hostCopy(mixture), fl = hostCopy(liquid);
  for (const auto& field : {f, fl}) {
    EXPECT_DOUBLE_EQ(field(1, 0), -1e4);
    EXPECT_DOUBLE_EQ(field(3, 0), -2e4);
    EXPECT_DOUBLE_EQ(field(5, 0), -1e4);
    EXPECT_NEAR(field(3, 1), 0.0, 1e-12);
    EXPECT_EQ(field(0, 0), 0.0);
  }
  const Mesh triangles = test::rectangleMesh(2, 1, 2.0, 1.0, ElementType::Tri3);
  const StageBoundaryConditions on_top(triangles,
                                       stageWith({test::liquidPressure("pond", "top", 1e3)}));
  loadsOn(triangles, on_top, mixture, liquid);
  const auto g = hostCopy(liquid);
  EXPECT_NEAR(g(3, 1), -500.0, 1e-9);
  EXPECT_NEAR(g(4, 1), -1000.0, 1e-9);
  EXPECT_NEAR(g(4, 0), 0.0, 1e-9);
  // p^ = 0 (drained) is the natural condition: no load is made at all.
  const StageBoundaryConditions drained(mesh, stageWith({test::liquidPressure("top", "top", 0.0)}));
  EXPECT_TRUE(drained.liquidPressures().empty());
}

TEST(StageBoundaryConditions, SuctionLoadsTheLiquidOnly) {
  // p^ = -1e4 Pa (suction) on the right side (n = +x) of the 1 x 2 mesh of 1 m elements.
  // Liquid (4.41): -p^ n L / 2 = +5e3 at nodes 1 and 5, +1e4 at node 3 (x: pulled outward).
  // Mixture (4.42): the total traction against air is 0 (mixtureLoadPressure(-1e4) = 0), so
  // no mixture load; the full -p^ n would be the same +5e3 / +1e4, and Bishop's
  // -S_L p^ n (sigma' n = 0) with S_L = 0.9 would be +4.5e3 / +9e3.
  const Mesh mesh = test::rectangleMesh(1, 2, 1.0, 2.0, ElementType::Quad4);
  const StageBoundaryConditions conditions(
      mesh, stageWith({test::liquidPressure("dry face", "right", -1e4)}));
  Kokkos::View<Real*[kDim], MemSpace> mixture, liquid;
  loadsOn(mesh, conditions, mixture, liquid);
  const auto f = hostCopy(mixture), fl = hostCopy(liquid);
  EXPECT_DOUBLE_EQ(fl(1, 0), 5e3);
  EXPECT_DOUBLE_EQ(fl(3, 0), 1e4);
  EXPECT_DOUBLE_EQ(fl(5, 0), 5e3);
  for (int i = 0; i < mesh.numNodes(); ++i)
    for (int d = 0; d < kDim; ++d) EXPECT_EQ(f(i, d), 0.0) << "node " << i;
  EXPECT_EQ(mixtureLoadPressure(-1e4), 0.0);
  EXPECT_EQ(mixtureLoadPressure(2e4), 2e4);  // free water: the full load (S_L = 1)
  EXPECT_EQ(mixtureLoadPressure(0.0), 0.0);
}

TEST(StageBoundaryConditions, LoadsSkipNodesWithoutMass) {
  const Mesh mesh = test::rectangleMesh(2, 1, 2.0, 1.0, ElementType::Quad4);
  const StageBoundaryConditions conditions(mesh,
                                           stageWith({test::traction("load", "top", 0.0, -1e4)}));
  Kokkos::View<Real*, MemSpace> mass("mass", mesh.numNodes());
  auto m = Kokkos::create_mirror_view(mass);
  for (int i = 0; i < mesh.numNodes(); ++i) m(i) = i == 5 ? 0.0 : 1.0;  // soil left node 5
  Kokkos::deep_copy(mass, m);
  Kokkos::View<Real*[kDim], MemSpace> mixture("mixture", 6), liquid("liquid", 6);
  conditions.addNodalForces(0.0, mass, mixture, liquid);
  const auto f = hostCopy(mixture);
  EXPECT_DOUBLE_EQ(f(4, 1), -1e4);
  EXPECT_EQ(f(5, 1), 0.0);
}

TEST(StageBoundaryConditions, ImpermeableSidesLockTheNormalComponent) {
  // 2 x 2 quads on [0,2]^2: nodes 0..8 row by row. Bottom side set: normal -y -> lock y on
  // nodes 0, 1, 2; left side set: normal -x -> lock x on 0, 3, 6. Node 0 gets both.
  const Mesh mesh = test::rectangleMesh(2, 2, 2.0, 2.0, ElementType::Quad4);
  const StageBoundaryConditions conditions(
      mesh, stageWith({test::impermeable("base", "bottom"), test::impermeable("wall", "left"),
                       test::solidFixity("fixed", "bottom", true, true)}));
  const NodalConstraints& c = conditions.constraints();
  EXPECT_EQ(c.flagsOf(0), kLiquidLockedX | kLiquidLockedY | kSolidFixedX | kSolidFixedY);
  EXPECT_EQ(c.flagsOf(1), kLiquidLockedY | kSolidFixedX | kSolidFixedY);
  EXPECT_EQ(c.flagsOf(3), kLiquidLockedX);
  EXPECT_EQ(c.flagsOf(4), 0u);
  EXPECT_EQ(c.count(), 5);  // nodes 0, 1, 2, 3, 6

  // The same from node sets: the direction comes from the mesh-boundary sides joining them.
  BoundarySpec from_nodes;
  from_nodes.name = "wall";
  from_nodes.kind = BoundaryKind::LiquidFixity;
  from_nodes.node_set = "right";
  const StageBoundaryConditions by_nodes(mesh, stageWith({from_nodes}));
  EXPECT_EQ(by_nodes.constraints().flagsOf(2), kLiquidLockedX);
  EXPECT_EQ(by_nodes.constraints().flagsOf(5), kLiquidLockedX);
  EXPECT_EQ(by_nodes.constraints().flagsOf(8), kLiquidLockedX);
}

TEST(StageBoundaryConditions, InclinedImpermeableSideIsAnInputError) {
  Mesh mesh = test::rectangleMesh(1, 1, 1.0, 1.0, ElementType::Quad4);
  auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  X(3, 0) = 1.5;  // top-right node moved: the right side leans
  Kokkos::deep_copy(mesh.coordinates, X);
  try {
    StageBoundaryConditions(mesh, stageWith({test::impermeable("slope", "right")}));
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Stages/flood/Boundary Conditions/slope");
    EXPECT_NE(std::string(error.what()).find("axis-aligned"), std::string::npos);
  }
}

TEST(NodalConstraints, ConstrainVelocitiesFixesSolidAndLocksLiquid) {
  NodalConstraints constraints;
  constraints.add(0, kSolidFixedX | kSolidFixedY | kLiquidLockedY);
  constraints.add(1, kLiquidLockedX);
  constraints.finalise();
  Kokkos::View<Real*[kDim], MemSpace> vs("vs", 3), vl("vl", 3);
  Kokkos::deep_copy(vs, 1.0);
  Kokkos::deep_copy(vl, 2.0);
  constraints.constrainVelocities(vs, vl);
  const auto s = hostCopy(vs), l = hostCopy(vl);
  EXPECT_EQ(s(0, 0), 0.0);
  EXPECT_EQ(s(0, 1), 0.0);
  EXPECT_EQ(l(0, 0), 2.0);  // x not locked: the liquid may flow along a fixed base
  EXPECT_EQ(l(0, 1), 0.0);  // locked to the (fixed) solid
  EXPECT_EQ(s(1, 0), 1.0);
  EXPECT_EQ(l(1, 0), 1.0);  // moves with the solid
  EXPECT_EQ(l(1, 1), 2.0);
  EXPECT_EQ(l(2, 0), 2.0);  // unconstrained node untouched
}

TEST(NodalConstraints, FixityKeepsTheMappedRelativeVelocityWhenAsked) {
  // A base node under a body that the remap says moves at (0.04, -0.06) m/s with its liquid
  // 1 mm/s faster downwards: the fixity stops the solid; the liquid keeps either all its
  // velocity (the thesis: 6.1 cm/s of Darcy flux out of a base the body cannot cross) or
  // only its relative velocity (-1 mm/s).
  NodalConstraints constraints;
  constraints.add(0, kSolidFixedX | kSolidFixedY);
  constraints.add(1, kSolidFixedX | kSolidFixedY | kLiquidLockedY);  // sealed base
  constraints.add(2, kLiquidLockedX);                                // no fixity
  constraints.finalise();
  Kokkos::View<Real*[kDim], MemSpace> vs("vs", 3), vl("vl", 3);
  const auto fill = [&] {
    auto s = Kokkos::create_mirror_view(vs);
    auto l = Kokkos::create_mirror_view(vl);
    for (int i = 0; i < 3; ++i) {
      s(i, 0) = 0.04, s(i, 1) = -0.06;
      l(i, 0) = 0.04, l(i, 1) = -0.061;
    }
    Kokkos::deep_copy(vs, s);
    Kokkos::deep_copy(vl, l);
  };
  fill();
  constraints.constrainVelocities(vs, vl);  // the thesis
  auto l = hostCopy(vl);
  EXPECT_EQ(l(0, 0), 0.04);
  EXPECT_EQ(l(0, 1), -0.061);
  fill();
  constraints.constrainVelocities(vs, vl, true);
  const auto s = hostCopy(vs);
  l = hostCopy(vl);
  EXPECT_EQ(s(0, 0), 0.0);
  EXPECT_EQ(s(0, 1), 0.0);
  EXPECT_EQ(l(0, 0), 0.0);
  EXPECT_DOUBLE_EQ(l(0, 1), -0.001);
  EXPECT_EQ(l(1, 0), 0.0);   // fixed in x: relative velocity 0 there as well
  EXPECT_EQ(l(1, 1), 0.0);   // locked: at rest with the fixed solid
  EXPECT_EQ(s(2, 0), 0.04);  // no fixity: the option changes nothing
  EXPECT_EQ(l(2, 0), 0.04);
  EXPECT_EQ(l(2, 1), -0.061);
  // applied twice (the hydraulic correction's pass): nothing more is removed
  constraints.constrainVelocities(vs, vl, true);
  EXPECT_DOUBLE_EQ(hostCopy(vl)(0, 1), -0.001);
}

}  // namespace
}  // namespace argine
