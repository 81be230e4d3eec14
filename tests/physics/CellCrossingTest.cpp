// [LargeDeformation][GIMP][B-spline] Cell crossing: a soft column settling under its own
// weight, its points moving across cells. The exact large-deformation answer: equilibrium
// in the deformed column gives every point the weight of the material above it, sigma_yy =
// -rho_0 g (H - Y) with Y its initial height (mass conservation, rho dy = rho_0 dY), and with
// argine's rate form (sigma = E_oed ln(stretch) in uniaxial strain) its height is
// y(Y) = (exp(-k (H - Y)) - exp(-k H)) / k, k = rho_0 g / E_oed. Linear shape functions stall
// under refinement (the internal force jumps as points cross cell edges); GIMP and B-splines
// converge. verification/cell_crossing charts the same column against cost.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "Harness.hpp"
#include "argine/points/Seeding.hpp"

namespace argine {
namespace {

using test::hostCopy;

struct ColumnErrors {
  Real position = 0;  ///< RMS of (y - y_exact) over the settlement of the top
  Real stress = 0;    ///< RMS of (sigma_yy - exact) over rho_0 g H
};

/// The column of `cells` cells (1 m high, one cell wide, 2 x 2 points a cell), settled
/// quasi-statically under gravity (local damping 0.7, 6 s), and its errors.
ColumnErrors settledColumn(ShapeFamily family, TransferScheme scheme, int cells) {
  const Real height = 1.0, width = height / cells, young = 1e5;  // nu = 0: E_oed = E
  // rho_0 g H / E = 0.156: the base is compressed by 14 %, the top settles by 7.5 cm, more
  // than a cell from 16 cells on.
  const MaterialSpec soil = test::elasticMaterial("soil", PhaseModel::Dry, young, 0.0, 0.4);
  Mesh mesh = test::rectangleMesh(1, cells, width, height, ElementType::Quad4);
  mesh.structured.cells[0] = 1;
  mesh.structured.cells[1] = cells;
  mesh.structured.spacing[0] = width;
  mesh.structured.spacing[1] = height / cells;
  mesh.shape_functions = family;
  MaterialPoints points = seedMaterialPoints(mesh, {SeedRequest{0, 0, 4}});
  std::vector<MaterialSpec> materials{soil};
  initialisePointState(materials, points);
  ExplicitTwoPhaseSolver solver(mesh, points, materials);
  StageSpec stage = test::makeStage("settle", SolverKind::QuasiStatic, 9.81, 0.7,
                                    {test::solidFixity("base", "bottom", true, true),
                                     test::solidFixity("left", "left", true, false),
                                     test::solidFixity("right", "right", true, false)},
                                    {CriterionKind::CflDry});
  stage.transfer = scheme;
  solver.beginStage(stage);
  test::runUntil(solver, 6.0);

  const Real rho = 0.6 * 2650;  // (1 - n) rho_S, dry
  const Real k = rho * 9.81 / young;
  const Real settlement = height - (1 - std::exp(-k * height)) / k;
  const auto y0 = hostCopy(points.initial_position);
  const auto y = hostCopy(points.position);
  const auto stress = hostCopy(points.stress_effective);
  Real position = 0, sigma = 0;
  for (int p = 0; p < points.count; ++p) {
    const Real Y = y0(p, 1);
    const Real e_y = (y(p, 1) - (std::exp(-k * (height - Y)) - std::exp(-k * height)) / k);
    const Real e_s = (stress(p, YY) + rho * 9.81 * (height - Y)) / (rho * 9.81 * height);
    position += e_y * e_y;
    sigma += e_s * e_s;
  }
  return {std::sqrt(position / points.count) / settlement, std::sqrt(sigma / points.count)};
}

TEST(CellCrossing, GridShapesConvergeWhereLinearShapesStall) {
  // Measured (2 x 2 points a cell; position error over the settlement / stress error over
  // rho g H, at 8, 16, 32 cells):
  //   linear FLIP      3.7 / 12 / 24 %          11.9 / 17.7 / 20 %   (grows)
  //   GIMP APIC        0.41 / 0.23 / 0.15 %     2.3 / 1.6 / 1.2 %
  //   B-spline APIC    0.43 / 0.28 / 0.21 %     1.6 / 1.6 / 1.4 %
  // The grid families converge (order ~0.5 in position here) until the points' quadrature
  // error dominates (fixed points a cell); the stress of the strongly compressed base keeps
  // a quadrature error of ~1.5 % at 4 points a cell (0.5 % at 16).
  const int cells[3] = {8, 16, 32};
  ColumnErrors linear[3], gimp[3], spline[3];
  for (int k = 0; k < 3; ++k) {
    linear[k] = settledColumn(ShapeFamily::Linear, TransferScheme::Flip, cells[k]);
    gimp[k] = settledColumn(ShapeFamily::Gimp, TransferScheme::Apic, cells[k]);
    spline[k] = settledColumn(ShapeFamily::BSpline, TransferScheme::Apic, cells[k]);
    std::printf(
        "  %2d cells: position error linear %.2e GIMP %.2e B-spline %.2e; stress %.2e "
        "%.2e %.2e\n",
        cells[k], linear[k].position, gimp[k].position, spline[k].position, linear[k].stress,
        gimp[k].stress, spline[k].stress);
  }
  for (const ColumnErrors* family : {gimp, spline}) {
    EXPECT_LT(family[1].position, family[0].position);
    EXPECT_LT(family[2].position, family[1].position);
    EXPECT_LT(family[2].position, 0.1 * linear[2].position);
    EXPECT_LT(family[2].stress, 0.2 * linear[2].stress);
    EXPECT_GT(std::log2(family[0].position / family[2].position) / 2, 0.3);  // observed order
  }
  EXPECT_GT(linear[2].position, 2 * linear[0].position);  // linear: worse as it refines
}

}  // namespace
}  // namespace argine
