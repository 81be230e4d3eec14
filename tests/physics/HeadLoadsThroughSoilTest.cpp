// [2Phase][Boundary] A total head's pressure through the soil's volume (`Hydraulic Loads:
// through the soil`, physics/HeadLoadsThroughSoil.hpp, doc/theory.md Sec. 5.5): the field
// by hand, and its nodal loads on a block of uGIMP points against the surface integral
// -oint N_i p^ n that Gauss's theorem makes of them.
#include <gtest/gtest.h>

#include <cmath>

#include "../transfer/TestScenes.hpp"
#include "argine/physics/HeadLoadsThroughSoil.hpp"
#include "argine/physics/PointBorneLoads.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {
namespace {

using test::hostCopy;

TEST(HeadPressureField, HydrostaticBelowTheLevelAndTheRuleAbove) {
  HeadPressureField field;
  field.rho_g = 9810;
  field.head = 2.0;
  Real p, dp;
  field.liquid(1.5, p, dp);  // 0.5 m below the level
  EXPECT_DOUBLE_EQ(p, 4905);
  EXPECT_DOUBLE_EQ(dp, -9810);
  field.mixture(1.5, p, dp);
  EXPECT_DOUBLE_EQ(p, 4905);
  EXPECT_DOUBLE_EQ(dp, -9810);
  field.liquid(2.5, p, dp);  // above: a seepage face's 0
  EXPECT_EQ(p, 0);
  EXPECT_EQ(dp, 0);
  field.suction_above = true;  // linear suction: the line goes on for the liquid ...
  field.liquid(2.5, p, dp);
  EXPECT_DOUBLE_EQ(p, -4905);
  EXPECT_DOUBLE_EQ(dp, -9810);
  field.mixture(2.5, p, dp);  // ... and the mixture, against air, takes none of it
  EXPECT_EQ(p, 0);
  EXPECT_EQ(dp, 0);
}

/// A block of 2 x 2 points a cell filling the bottom 3 rows of a 4 x 4 uGIMP grid of 0.25 m
/// cells (surface at y = 0.75 m, on the cell edges) under a head of 2 m: the nodal loads.
struct BlockLoads {
  static constexpr int kCells = 4;
  static constexpr Real kH = 0.25, kTop = 0.75, kRhoG = 9810, kHead = 2.0;
  Kokkos::View<Real**, MemSpace>::HostMirror f;  // node x (mixture x, y, liquid x, y)
  explicit BlockLoads(int material) {
    const Mesh mesh = test::gridMesh(kCells, kCells, 1.0, 1.0, ShapeFamily::Gimp);
    MaterialPoints points = test::seedUniform(mesh, material, [](int e) { return e / kCells < 3; });
    PointShapes shapes;
    evaluatePointShapes(mesh, points, shapes);
    PointBorneLoadFields fields;
    fields.allocate(mesh.numNodes());
    HeadPressureField field;
    field.rho_g = kRhoG;
    field.head = kHead;
    spreadHeadLoadsThroughSoil(field, points, shapes, test::liquidFlags(), fields);
    f = hostCopy(fields.spread_i);
  }
  static int node(int i, int j) { return j * (kCells + 1) + i; }
  static Real pressure(Real y) { return kRhoG * (kHead - y); }
};

TEST(HeadLoadsThroughSoil, TheVolumeSumIsTheSurfaceIntegralOfTheBlock) {
  const BlockLoads block(0);  // liquid-carrying
  using B = BlockLoads;
  Real resultant[2] = {0, 0};
  for (int j = 0; j <= B::kCells; ++j)
    for (int i = 0; i <= B::kCells; ++i)
      for (int d = 0; d < kDim; ++d) {
        const int n = B::node(i, j);
        resultant[d] += block.f(n, d);
        EXPECT_EQ(block.f(n, d), block.f(n, kDim + d));  // the liquid's: the same field
        // inside the block (not on its outline) nothing: the sums telescope
        if (i > 0 && i < B::kCells && j > 0 && j < 3) {
          EXPECT_NEAR(block.f(n, d), 0.0, 1e-9) << "node " << i << ", " << j;
        }
      }
  // Gauss: the buoyancy rho g V upward, nothing sideways
  EXPECT_NEAR(resultant[0], 0.0, 1e-9);
  EXPECT_NEAR(resultant[1], B::kRhoG * 1.0 * B::kTop, 1e-9 * B::kRhoG);
  // the top face at y = 0.75 m: f_y = -p^(0.75) int N_i dx, exactly, h inside, h / 2 at the
  // corners (in 1D the points' stresses telescope to the surface: HeadLoadsThroughSoil.hpp)
  for (int i = 0; i <= B::kCells; ++i) {
    const Real width = (i == 0 || i == B::kCells) ? B::kH / 2 : B::kH;
    EXPECT_NEAR(block.f(B::node(i, 3), 1), -B::pressure(B::kTop) * width, 1e-9) << "node " << i;
  }
  // the left face x = 0: f_x = +int N_j p^ dy, here by the points' midpoint rule in y (the
  // exact integral differs by (l^2/3) |dp/dy| h = 12.8 N/m, 0.3 %, at most)
  for (int j = 1; j < 3; ++j) {
    const Real y = j * B::kH;  // int N_j p^ dy = h p^(y_j) for p^ linear, whole hat inside
    EXPECT_NEAR(block.f(B::node(0, j), 0), B::kH * B::pressure(y), 0.005 * B::kH * B::pressure(y));
    EXPECT_NEAR(block.f(B::node(B::kCells, j), 0), -B::kH * B::pressure(y),
                0.005 * B::kH * B::pressure(y));
  }
}

TEST(HeadLoadsThroughSoil, DryPointsLoadTheMixtureOnly) {
  const BlockLoads dry(1), wet(0);  // material 1 carries no liquid (liquidFlags)
  for (int n = 0; n < (BlockLoads::kCells + 1) * (BlockLoads::kCells + 1); ++n)
    for (int d = 0; d < kDim; ++d) {
      EXPECT_EQ(dry.f(n, kDim + d), 0.0);
      EXPECT_EQ(dry.f(n, d), wet.f(n, d));
    }
}

}  // namespace
}  // namespace argine
