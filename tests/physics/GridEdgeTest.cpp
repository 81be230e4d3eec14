// [Explicit][GIMP][B-spline] Points flowing over a floor that is the grid's edge stay half
// their half-width clear of its line (clearOfGridEdges). Without it the bottom points of this
// small collapse sink below that (GIMP APIC to 0.85 of it, B-spline APIC to 0.98) and, in the
// V7 collapse, onto the line itself, where the folded weight of the line above vanishes while
// its gradient stays 1/h: APIC then lifted a point off the floor at 1.5 m/s (doc/theory.md
// Sec. 3.11, "Points at the grid's edge").
#include <gtest/gtest.h>

#include <cmath>
#include <tuple>

#include "Harness.hpp"

namespace argine {
namespace {

using test::hostCopy;

class GridEdge : public ::testing::TestWithParam<std::tuple<ShapeFamily, TransferScheme>> {};

TEST_P(GridEdge, CollapsingColumnsPointsStayClearOfTheFloorLine) {
  // A small granular collapse (dry sand column 2 x 16 cells of 1 cm, a = 8, Mohr-Coulomb
  // 30 deg, psi = 0, against a smooth wall onto a floor with mu = 0.5): the flow drives the
  // bottom points down towards the floor line, which is the grid's edge.
  const auto [family, scheme] = GetParam();
  constexpr int kNx = 40, kNy = 17;
  constexpr Real kH = 0.01;
  Mesh mesh = test::rectangleMesh(kNx, kNy, kNx * kH, kNy * kH, ElementType::Quad4);
  mesh.structured.cells[0] = kNx;
  mesh.structured.cells[1] = kNy;
  mesh.structured.origin[0] = mesh.structured.origin[1] = 0;
  mesh.structured.spacing[0] = mesh.structured.spacing[1] = kH;
  mesh.shape_functions = family;
  MaterialPoints points = test::seedUniform(mesh, 0, [](int e) {
    const int i = e % kNx, j = e / kNx;
    return i < 2 && j < 16;
  });
  MaterialSpec sand = test::elasticMaterial("sand", PhaseModel::Dry, 1e6, 0.3, 0.4);
  sand.solid.model = SolidModel::MohrCoulomb;
  sand.solid.cohesion = 0;
  sand.solid.friction_angle = 30 * M_PI / 180;
  std::vector<MaterialSpec> materials{sand};
  initialisePointState(materials, points);
  BoundarySpec floor;
  floor.name = "floor";
  floor.kind = BoundaryKind::FrictionalWall;
  floor.side_set = "bottom";
  floor.friction_coefficient = 0.5;
  ExplicitTwoPhaseSolver solver(mesh, points, materials);
  StageSpec stage = test::makeStage("collapse", SolverKind::Explicit, 9.81, 0.0,
                                    {test::solidFixity("wall", "left", true, false), floor},
                                    {CriterionKind::CflDry});
  stage.transfer = scheme;
  solver.beginStage(stage);
  Real lowest = 1;
  test::runUntil(solver, 0.8, [&] {
    const auto x = hostCopy(points.position);
    for (int p = 0; p < points.count; ++p) lowest = std::min(lowest, x(p, 1));
  });
  // 2 x 2 points a cell: half-width l = 1/4 cell, kept l / 2 = 1/8 cell from the edge line
  const Real clearance = 0.125 * kH;
  std::printf("[ measured ] lowest point %.3e m (clearance %.3e m)\n", lowest, clearance);
  EXPECT_GE(lowest, clearance * (1 - 1e-12));
  EXPECT_EQ(solver.diagnostics().lost_points, 0);
}

INSTANTIATE_TEST_SUITE_P(
    Families, GridEdge,
    ::testing::Values(std::make_tuple(ShapeFamily::Gimp, TransferScheme::Apic),
                      std::make_tuple(ShapeFamily::BSpline, TransferScheme::Apic),
                      std::make_tuple(ShapeFamily::Gimp, TransferScheme::Tpic)),
    [](const auto& info) {
      const ShapeFamily family = std::get<0>(info.param);
      const TransferScheme scheme = std::get<1>(info.param);
      return std::string(family == ShapeFamily::Gimp ? "Gimp" : "BSpline") +
             (scheme == TransferScheme::Apic ? "Apic" : "Tpic");
    });

}  // namespace
}  // namespace argine
