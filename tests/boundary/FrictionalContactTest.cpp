// [Boundary][Contact] Resolution of frictional walls (normals, corners, fixities, liquid
// locks, bad input) and their velocity form.
#include <gtest/gtest.h>

#include <cmath>

#include "../transfer/TestScenes.hpp"
#include "argine/boundary/BoundaryConditions.hpp"
#include "argine/boundary/FrictionalContact.hpp"
#include "argine/core/Error.hpp"

namespace argine {
namespace {

using test::hostCopy;

BoundarySpec frictionalWall(const std::string& name, const std::string& side_set, Real mu,
                            bool impermeable = true) {
  BoundarySpec b;
  b.name = name;
  b.kind = BoundaryKind::FrictionalWall;
  b.side_set = side_set;
  b.friction_coefficient = mu;
  b.wall_impermeable = impermeable;
  return b;
}

StageSpec stageWith(std::vector<BoundarySpec> boundaries) {
  StageSpec stage;
  stage.name = "slide";
  stage.boundaries = std::move(boundaries);
  return stage;
}

// ---------------------------------------------------------------- resolution

TEST(FrictionalContact, SideSetNormalsAndCornersOfABox) {
  // 2 x 2 quads on [0,2]^2, nodes 0..8 row by row. Floor (mu 0.3) and left wall (mu 0.5):
  // floor nodes 1, 2 get n = (0, -1), wall nodes 3, 6 get (-1, 0); node 0 is the corner
  // (90 degrees): held, with the rougher mu.
  const Mesh mesh = test::rectangleMesh(2, 2, 2.0, 2.0, ElementType::Quad4);
  const StageBoundaryConditions conditions(mesh,
                                           stageWith({frictionalWall("floor", "bottom", 0.3),
                                                      frictionalWall("wall", "left", 0.5, false)}));
  const FrictionalContact& contact = conditions.frictionalContact();
  EXPECT_EQ(contact.count(), 5);
  const ContactNode* floor = contact.find(1);
  ASSERT_NE(floor, nullptr);
  EXPECT_DOUBLE_EQ(floor->normal[0], 0.0);
  EXPECT_DOUBLE_EQ(floor->normal[1], -1.0);
  EXPECT_EQ(floor->friction, 0.3);
  EXPECT_EQ(floor->flags, kContactImpermeable);
  EXPECT_EQ(contact.find(2)->flags, kContactImpermeable);  // end of the set: one side
  const ContactNode* wall = contact.find(6);
  EXPECT_DOUBLE_EQ(wall->normal[0], -1.0);
  EXPECT_EQ(wall->flags, 0u);  // permeable
  const ContactNode* corner = contact.find(0);
  EXPECT_EQ(corner->flags, kContactHeld | kContactImpermeable);
  EXPECT_EQ(corner->friction, 0.5);
  EXPECT_EQ(contact.find(4), nullptr);
  EXPECT_EQ(conditions.constraints().count(), 0);
}

TEST(FrictionalContact, GentleKinksAverageTheNormalsSharpOnesHold) {
  // 3 x 1 quads on [0,3] x [0,1]; bottom nodes 0..3. Node 1 lowered by 0.05 m: the floor
  // kinks there by 2 atan(0.05) = 5.7 degrees (mean normal (0, -1)), node 2 by 2.9 degrees.
  // Lowered by 0.2 m instead, node 1 kinks by 22.6 degrees: held.
  for (const Real drop : {0.05, 0.2}) {
    Mesh mesh = test::rectangleMesh(3, 1, 3.0, 1.0, ElementType::Quad4);
    auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
    X(1, 1) = -drop;
    Kokkos::deep_copy(mesh.coordinates, X);
    const StageBoundaryConditions conditions(mesh,
                                             stageWith({frictionalWall("floor", "bottom", 0.3)}));
    const ContactNode* kink = conditions.frictionalContact().find(1);
    ASSERT_NE(kink, nullptr);
    if (drop < 0.1) {
      EXPECT_EQ(kink->flags & kContactHeld, 0u);
      EXPECT_NEAR(kink->normal[0], 0.0, 1e-15);  // (-0.05, -1) and (0.05, -1) averaged
      EXPECT_NEAR(kink->normal[1], -1.0, 1e-15);
      const ContactNode* next = conditions.frictionalContact().find(2);
      EXPECT_NEAR(next->normal[0], std::sin(0.5 * std::atan(0.05)), 1e-12);  // mean normal
    } else {
      EXPECT_NE(kink->flags & kContactHeld, 0u);
    }
  }
}

TEST(FrictionalContact, NodeSetNormalFromGeometryOrDeckAndBadInput) {
  const Mesh mesh = test::rectangleMesh(2, 2, 2.0, 2.0, ElementType::Quad4);
  BoundarySpec by_nodes = frictionalWall("floor", "", 0.4);
  by_nodes.node_set = "bottom";
  const StageBoundaryConditions geometric(mesh, stageWith({by_nodes}));
  for (const int node : {0, 1, 2}) {  // corner node 0: only the floor joins two set nodes
    EXPECT_DOUBLE_EQ(geometric.frictionalContact().find(node)->normal[1], -1.0);
    EXPECT_EQ(geometric.frictionalContact().find(node)->flags, kContactImpermeable);
  }
  by_nodes.has_normal = true;
  by_nodes.normal = {0.6, -0.8};
  const StageBoundaryConditions given(mesh, stageWith({by_nodes}));
  EXPECT_EQ(given.frictionalContact().find(1)->normal[0], 0.6);

  // A node set holding an interior node (4) has no wall normal there.
  Mesh odd = mesh;
  odd.node_sets.push_back(NodeSet{"odd", 9, {0, 1, 4}});
  BoundarySpec inner = frictionalWall("inner", "", 0.4);
  inner.node_set = "odd";
  try {
    StageBoundaryConditions(odd, stageWith({inner}));
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Stages/slide/Boundary Conditions/inner/Node Set");
    EXPECT_NE(std::string(error.what()).find("node 5 (1-based)"), std::string::npos);
    EXPECT_NE(std::string(error.what()).find("Normal"), std::string::npos);
  }
  try {
    StageBoundaryConditions(mesh, stageWith({frictionalWall("floor", "base", 0.4)}));
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), "Stages/slide/Boundary Conditions/floor");
    EXPECT_NE(std::string(error.what()).find("side set 'base'"), std::string::npos);
  }
}

TEST(FrictionalContact, FixitiesWinAndImpermeableLocksMoveToTheWall) {
  // Floor wall on 2 x 2 quads, a roller (x fixed) on the left, an impermeable floor too.
  // Node 0: contact flags carry the fixity and the floor's y lock, which NodalConstraints
  // no longer applies (the wall does, after its contact); node 3 keeps its roller only.
  const Mesh mesh = test::rectangleMesh(2, 2, 2.0, 2.0, ElementType::Quad4);
  const StageBoundaryConditions conditions(
      mesh, stageWith({frictionalWall("floor", "bottom", 0.3),
                       test::solidFixity("roller", "left", true, false),
                       test::impermeable("seal", "bottom")}));
  const FrictionalContact& contact = conditions.frictionalContact();
  EXPECT_EQ(contact.find(0)->flags, kContactImpermeable | kSolidFixedX | kLiquidLockedY);
  EXPECT_EQ(contact.find(1)->flags, kContactImpermeable | kLiquidLockedY);
  const NodalConstraints& constraints = conditions.constraints();
  EXPECT_EQ(constraints.flagsOf(0), kSolidFixedX);
  EXPECT_EQ(constraints.flagsOf(1), 0u);
  EXPECT_EQ(constraints.flagsOf(3), kSolidFixedX);
  EXPECT_EQ(constraints.count(), 3);  // nodes 0, 3, 6
}

// ---------------------------------------------------------------- velocity form

TEST(FrictionalContact, VelocityFormProjectsTheSolidAndLocksTheLiquidNormal) {
  // Floor of 2 x 1 quads (nodes 0, 1, 2 on it), mu = 0.3, impermeable. Masses M_S = 600,
  // M_L = 400 kg at nodes 0 and 1; node 2 has no soil.
  //  node 0: v_S = (2, -0.5): solid friction coefficient 0.3 x 1000 / 600 = 0.5, |v_t|
  //          2 - 0.25 = 1.75; v_L = (1, -3) takes v_S's normal part 0: (1, 0);
  //  node 1: v_S = (1, 0.4) leaves the floor: free; v_L = (0, 0) gets its normal part 0.4;
  //  node 2: untouched.
  const Mesh mesh = test::rectangleMesh(2, 1, 2.0, 1.0, ElementType::Quad4);
  const StageBoundaryConditions conditions(mesh,
                                           stageWith({frictionalWall("floor", "bottom", 0.3)}));
  Kokkos::View<Real*, MemSpace> ms("ms", 6), ml("ml", 6);
  Kokkos::View<Real*[kDim], MemSpace> vs("vs", 6), vl("vl", 6);
  auto hms = Kokkos::create_mirror_view(ms), hml = Kokkos::create_mirror_view(ml);
  auto hvs = Kokkos::create_mirror_view(vs), hvl = Kokkos::create_mirror_view(vl);
  for (int i = 0; i < 2; ++i) hms(i) = 600, hml(i) = 400;
  hvs(0, 0) = 2, hvs(0, 1) = -0.5, hvl(0, 0) = 1, hvl(0, 1) = -3;
  hvs(1, 0) = 1, hvs(1, 1) = 0.4;
  hvs(2, 0) = 5, hvs(2, 1) = -5;
  Kokkos::deep_copy(ms, hms), Kokkos::deep_copy(ml, hml);
  Kokkos::deep_copy(vs, hvs), Kokkos::deep_copy(vl, hvl);
  conditions.frictionalContact().constrainVelocities(ms, ml, vs, vl, false);
  const auto s = hostCopy(vs), l = hostCopy(vl);
  EXPECT_DOUBLE_EQ(s(0, 0), 1.75);
  EXPECT_EQ(s(0, 1), 0.0);
  EXPECT_EQ(l(0, 0), 1.0);
  EXPECT_EQ(l(0, 1), 0.0);
  EXPECT_EQ(s(1, 0), 1.0);
  EXPECT_EQ(s(1, 1), 0.4);
  EXPECT_EQ(l(1, 0), 0.0);
  EXPECT_EQ(l(1, 1), 0.4);
  EXPECT_EQ(s(2, 0), 5.0);
  EXPECT_EQ(s(2, 1), -5.0);
  // Run again on its own result: nothing changes (the solver re-applies it).
  conditions.frictionalContact().constrainVelocities(ms, ml, vs, vl, false);
  EXPECT_EQ(hostCopy(vs)(0, 0), 1.75);
}

}  // namespace
}  // namespace argine
