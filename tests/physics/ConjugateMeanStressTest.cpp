// `Conjugate Mean Stress` (physics/VolumetricAveraging.hpp): the forces do the work of the
// averaged increments. For any point strains and stresses, with element averages over
// part-filled cells of unequal weight,
//   sum_p V_p s_p : eps_bar_p = sum_p V_p (s_p + shift_p I) : eps_p   (the mixture) and
//   sum_p V_p p_p div_bar_p   = sum_p V_p (p_p + shift_p) div_p       (the liquid),
// eps_bar, div_bar what averageStrainIncrements gives; without the shifts the two sides
// differ. And the P2G reads the shifts as a change of the points' stress and p_L would
// (standard Quad4 and GIMP grid shapes).

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "../transfer/TestScenes.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/VolumetricAveraging.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/NodeRecords.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"

namespace argine {
namespace {

using test::hostCopy;

/// Saturation, p_L, effective stress and the three increments of every point, varying from
/// point to point; volumes scaled per cell (two cells part-filled, 0.2 and 0.05).
void fillPoints(MaterialPoints& points, PointRates& rates, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  auto volume = hostCopy(points.volume);
  const auto element = hostCopy(points.element);
  auto saturation = Kokkos::create_mirror_view(points.saturation);
  auto pressure = Kokkos::create_mirror_view(points.pressure_liquid);
  auto stress = Kokkos::create_mirror_view(points.stress_effective);
  auto strain = Kokkos::create_mirror_view(rates.strain_increment_p);
  auto divergence = Kokkos::create_mirror_view(rates.liquid_divergence_increment_p);
  auto flux = Kokkos::create_mirror_view(rates.content_flux_divergence_increment_p);
  for (int p = 0; p < points.count; ++p) {
    if (element(p) == 4) volume(p) *= 0.2;
    if (element(p) == 5) volume(p) *= 0.05;
    volume(p) *= 1 + 0.3 * u(rng);
    saturation(p) = 0.8 + 0.2 * u(rng);
    pressure(p) = 1e4 * u(rng);
    for (int k = 0; k < kStressComponents; ++k) stress(p, k) = -2e4 + 1.5e4 * u(rng);
    for (int k = 0; k < kStressComponents; ++k) strain(p, k) = 1e-4 * u(rng);
    divergence(p) = 1e-4 * u(rng);
    flux(p) = 1e-5 * u(rng);
  }
  Kokkos::deep_copy(points.volume, volume);
  Kokkos::deep_copy(points.saturation, saturation);
  Kokkos::deep_copy(points.pressure_liquid, pressure);
  Kokkos::deep_copy(points.stress_effective, stress);
  Kokkos::deep_copy(rates.strain_increment_p, strain);
  Kokkos::deep_copy(rates.liquid_divergence_increment_p, divergence);
  Kokkos::deep_copy(rates.content_flux_divergence_increment_p, flux);
}

/// sum_p V_p (s_p + shift_p I) : eps_p and sum_p V_p (p_p + shift_p) div_p, the mixture's total
/// stress with Bishop chi = S_L; no shift where `shift` is empty.
std::array<Real, 2> work(const MaterialPoints& points, const PointRates& rates,
                         const MeanStressShifts& shift) {
  const auto volume = hostCopy(points.volume);
  const auto saturation = hostCopy(points.saturation);
  const auto pressure = hostCopy(points.pressure_liquid);
  const auto stress = hostCopy(points.stress_effective);
  const auto strain = hostCopy(rates.strain_increment_p);
  const auto divergence = hostCopy(rates.liquid_divergence_increment_p);
  const bool shifted = shift.extent(0) > 0;
  const auto s = hostCopy(shift);
  std::array<Real, 2> w = {0, 0};
  for (int p = 0; p < points.count; ++p) {
    const Real diagonal = -saturation(p) * pressure(p) + (shifted ? s(p, 0) : 0);
    // engineering shear strain: s : eps = sxx exx + syy eyy + sxy gxy
    w[0] +=
        volume(p) * ((stress(p, XX) + diagonal) * strain(p, XX) +
                     (stress(p, YY) + diagonal) * strain(p, YY) + stress(p, XY) * strain(p, XY));
    w[1] += volume(p) * (pressure(p) + (shifted ? s(p, 1) : 0)) * divergence(p);
  }
  return w;
}

/// The soil of the tests: `averaging` of d eps_vol (element by default), forces conjugate
/// (never with the checkerboard filter: checkDeck).
MaterialSpec conjugateSoil(IncrementAveraging averaging = IncrementAveraging::Element) {
  MaterialSpec soil = test::elasticMaterial("soil", PhaseModel::Unsaturated, 5e7, 0.3, 0.4);
  soil.locking.volumetric_strain = averaging;
  soil.locking.conjugate_mean_stress = true;
  return soil;
}

/// The forces with the shifts do the work of the averaged increments, to rounding, and the
/// points' own stresses do not.
void expectForcesDoTheWorkOfTheAveragedIncrements(const Mesh& mesh, IncrementAveraging mode) {
  MaterialPoints points = test::seedUniform(mesh);
  const MaterialSpec soil = conjugateSoil(mode);
  const MaterialTable table({soil});
  PointShapes shapes;
  evaluatePointShapes(mesh, points, shapes);
  ActiveNodes active{mesh.numNodes()};
  active.rebuild(mesh, points);
  PointRates raw;
  raw.allocate(points.count);
  fillPoints(points, raw, 3);

  VolumetricAveraging averaging(table, mesh);
  ASSERT_TRUE(averaging.conjugatesMeanStress());
  averaging.averageMeanStresses(table, points, shapes, active);
  PointRates averaged;
  averaged.allocate(points.count);
  Kokkos::deep_copy(averaged.strain_increment_p, raw.strain_increment_p);
  Kokkos::deep_copy(averaged.liquid_divergence_increment_p, raw.liquid_divergence_increment_p);
  Kokkos::deep_copy(averaged.content_flux_divergence_increment_p,
                    raw.content_flux_divergence_increment_p);
  averaging.averageStrainIncrements(table, points, shapes, active, averaged);

  const auto of_averaged = work(points, averaged, {});
  const auto conjugate = work(points, raw, averaging.meanStressShifts());
  const auto own = work(points, raw, {});
  for (int c = 0; c < 2; ++c) {
    const Real scale = std::abs(of_averaged[c]);
    EXPECT_NEAR(conjugate[c], of_averaged[c], 1e-12 * scale) << (c == 0 ? "mixture" : "liquid");
    // the points' own stresses do other work: the test can fail
    EXPECT_GT(std::abs(own[c] - of_averaged[c]), 1e-3 * scale) << (c == 0 ? "mixture" : "liquid");
  }
}

TEST(ConjugateMeanStress, TheForcesDoTheWorkOfTheAveragedIncrements) {
  expectForcesDoTheWorkOfTheAveragedIncrements(
      test::rectangleMesh(3, 3, 1.5, 1.5, ElementType::Quad4), IncrementAveraging::Element);
}

// The nodal average q_p <- sum_i N_ip (sum_q N_iq V_q q_q / sum_q N_iq V_q) is self-adjoint in
// the weights V too (V_p A_pq is symmetric), so its conjugate is the same nodal average of the
// mean stress: B-bar for the nodal mixed discretisation.
TEST(ConjugateMeanStress, TheForcesDoTheWorkOfTheNodallyAveragedIncrements) {
  expectForcesDoTheWorkOfTheAveragedIncrements(
      test::rectangleMesh(3, 3, 1.5, 1.5, ElementType::Quad4), IncrementAveraging::Nodal);
  expectForcesDoTheWorkOfTheAveragedIncrements(
      test::rectangleMesh(3, 3, 1.5, 1.5, ElementType::Tri3), IncrementAveraging::Nodal);
}

TEST(ConjugateMeanStress, ShiftsAreTheCellMeanLessThePointsOwn) {
  // One material without the key beside the soil: its points keep their own (zero shift); a
  // cell of points of one mean stress and p_L, among neighbours of the same, keeps them.
  const Mesh mesh = test::rectangleMesh(3, 3, 1.5, 1.5, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh);
  const MaterialSpec soil = conjugateSoil();
  MaterialSpec plain = soil;
  plain.name = "plain";
  plain.locking.conjugate_mean_stress = false;
  const MaterialTable table({soil, plain});
  {
    auto material = Kokkos::create_mirror_view(points.material);
    auto saturation = Kokkos::create_mirror_view(points.saturation);
    auto pressure = Kokkos::create_mirror_view(points.pressure_liquid);
    auto stress = Kokkos::create_mirror_view(points.stress_effective);
    for (int p = 0; p < points.count; ++p) {
      material(p) = p == 0 ? 1 : 0;
      saturation(p) = 0.5;
      pressure(p) = 2000;
      // the same mean (s_xx + s_yy) / 2 = -3000 everywhere, different deviators
      stress(p, XX) = -3000 + 100 * p;
      stress(p, YY) = -3000 - 100 * p;
      stress(p, ZZ) = -1000;
      stress(p, XY) = 50 * p;
    }
    Kokkos::deep_copy(points.material, material);
    Kokkos::deep_copy(points.saturation, saturation);
    Kokkos::deep_copy(points.pressure_liquid, pressure);
    Kokkos::deep_copy(points.stress_effective, stress);
  }
  PointShapes shapes;
  evaluatePointShapes(mesh, points, shapes);
  ActiveNodes active{mesh.numNodes()};
  active.rebuild(mesh, points);
  VolumetricAveraging averaging(table, mesh);
  averaging.averageMeanStresses(table, points, shapes, active);
  const auto shift = hostCopy(averaging.meanStressShifts());
  for (int p = 0; p < points.count; ++p)
    for (int c = 0; c < 2; ++c) EXPECT_NEAR(shift(p, c), 0, 1e-9) << "point " << p;

  // Now one point of the centre cell at mean -3000 + 800 (total: less S p_L = 1000) and p_L
  // 2000 + 400: its cell's four points of equal volume average a quarter of its excess, the
  // other cells keep theirs.
  int raised = -1;
  {
    auto stress = hostCopy(points.stress_effective);
    auto pressure = hostCopy(points.pressure_liquid);
    auto material = hostCopy(points.material);
    const auto position = hostCopy(points.position);
    const auto volume = hostCopy(points.volume);
    for (int p = 0; p < points.count; ++p) {
      material(p) = 0;
      const bool in_centre = position(p, 0) > 0.5 && position(p, 0) < 1.0 && position(p, 1) > 0.5 &&
                             position(p, 1) < 1.0;
      if (!in_centre || raised >= 0) continue;
      raised = p;
      stress(p, XX) += 800;
      stress(p, YY) += 800;
      pressure(p) += 400;
    }
    ASSERT_GE(raised, 0);
    for (int p = 1; p < points.count; ++p) ASSERT_DOUBLE_EQ(volume(p), volume(0));
    Kokkos::deep_copy(points.stress_effective, stress);
    Kokkos::deep_copy(points.pressure_liquid, pressure);
    Kokkos::deep_copy(points.material, material);
  }
  averaging.averageMeanStresses(table, points, shapes, active);
  const auto shift2 = hostCopy(averaging.meanStressShifts());
  const auto element = hostCopy(points.element);
  int in_cell = 0;
  for (int p = 0; p < points.count; ++p) {
    const bool same_cell = element(p) == element(raised);
    in_cell += same_cell ? 1 : 0;
    // the total mean's excess: 800 - S 400 = 600 at the raised point, 150 its cell's average
    const Real own_excess = p == raised ? 600.0 : 0.0;
    EXPECT_NEAR(shift2(p, 0), (same_cell ? 150.0 : 0.0) - own_excess, 1e-9) << "point " << p;
    EXPECT_NEAR(shift2(p, 1), (same_cell ? 100.0 : 0.0) - (p == raised ? 400.0 : 0.0), 1e-9)
        << "point " << p;
  }
  EXPECT_EQ(in_cell, 4);
}

/// The P2G's forces with the shifts equal those of points whose stress and p_L carry them:
/// s'_xx, s'_yy + shift_0 + S shift_1 and p_L + shift_1 (S = 1 here, so shift_0 + shift_1).
void expectShiftsReadAsStress(const Mesh& mesh) {
  MaterialPoints points = test::seedUniform(mesh);
  PointRates rates;
  rates.allocate(points.count);
  fillPoints(points, rates, 11);
  {
    auto host = hostCopy(points.saturation);
    auto mass_solid = hostCopy(points.mass_solid);
    auto density = hostCopy(points.density_liquid);
    auto porosity = hostCopy(points.porosity);
    auto conductivity = hostCopy(points.conductivity);
    for (int p = 0; p < points.count; ++p) {
      host(p) = 1;
      mass_solid(p) = 1;
      density(p) = 1000;
      porosity(p) = 0.4;
      conductivity(p) = 1e-4;
    }
    Kokkos::deep_copy(points.saturation, host);
    Kokkos::deep_copy(points.mass_solid, mass_solid);
    Kokkos::deep_copy(points.density_liquid, density);
    Kokkos::deep_copy(points.porosity, porosity);
    Kokkos::deep_copy(points.conductivity, conductivity);
  }
  MeanStressShifts shift("shift", points.count);
  {
    auto s = Kokkos::create_mirror_view(shift);
    for (int p = 0; p < points.count; ++p) {
      s(p, 0) = 300 * std::sin(1.0 + p);
      s(p, 1) = 200 * std::cos(2.0 + p);
    }
    Kokkos::deep_copy(shift, s);
  }
  PointShapes shapes;
  evaluatePointShapes(mesh, points, shapes);
  ActiveNodes active{mesh.numNodes()};
  active.rebuild(mesh, points);
  TransferSettings with_shift;
  with_shift.mean_stress_shift = shift;
  GridFields shifted, moved;
  shifted.allocate(mesh.numNodes());
  moved.allocate(mesh.numNodes());
  NodeRecords records;
  mapPointsToGrid(points, shapes, test::liquidFlags(), 9.81, with_shift, active, records, shifted);
  {
    auto stress = hostCopy(points.stress_effective);
    auto pressure = hostCopy(points.pressure_liquid);
    const auto s = hostCopy(shift);
    for (int p = 0; p < points.count; ++p) {
      stress(p, XX) += s(p, 0) + s(p, 1);
      stress(p, YY) += s(p, 0) + s(p, 1);
      pressure(p) += s(p, 1);
    }
    Kokkos::deep_copy(points.stress_effective, stress);
    Kokkos::deep_copy(points.pressure_liquid, pressure);
  }
  mapPointsToGrid(points, shapes, test::liquidFlags(), 9.81, TransferSettings{}, active, records,
                  moved);
  const auto fm = hostCopy(shifted.force_mixture_i), fm_moved = hostCopy(moved.force_mixture_i);
  const auto fl = hostCopy(shifted.force_liquid_i), fl_moved = hostCopy(moved.force_liquid_i);
  int changed = 0;
  for (int i = 0; i < mesh.numNodes(); ++i)
    for (int d = 0; d < kDim; ++d) {
      EXPECT_NEAR(fm(i, d), fm_moved(i, d), 1e-9) << "node " << i;
      EXPECT_NEAR(fl(i, d), fl_moved(i, d), 1e-9) << "node " << i;
    }
  // and the shifts change the forces (against the points' unshifted stresses)
  GridFields plain;
  plain.allocate(mesh.numNodes());
  auto stress = hostCopy(points.stress_effective);
  auto pressure = hostCopy(points.pressure_liquid);
  const auto s = hostCopy(shift);
  for (int p = 0; p < points.count; ++p) {
    stress(p, XX) -= s(p, 0) + s(p, 1);
    stress(p, YY) -= s(p, 0) + s(p, 1);
    pressure(p) -= s(p, 1);
  }
  Kokkos::deep_copy(points.stress_effective, stress);
  Kokkos::deep_copy(points.pressure_liquid, pressure);
  mapPointsToGrid(points, shapes, test::liquidFlags(), 9.81, TransferSettings{}, active, records,
                  plain);
  const auto fm_plain = hostCopy(plain.force_mixture_i);
  for (int i = 0; i < mesh.numNodes(); ++i)
    if (std::abs(fm_plain(i, 0) - fm(i, 0)) > 1e-3) ++changed;
  EXPECT_GT(changed, mesh.numNodes() / 2);
}

TEST(ConjugateMeanStress, ThePointToGridReadsTheShiftsOnQuad4) {
  expectShiftsReadAsStress(test::rectangleMesh(3, 3, 1.5, 1.5, ElementType::Quad4));
}

TEST(ConjugateMeanStress, ThePointToGridReadsTheShiftsOnGimpGrid) {
  expectShiftsReadAsStress(test::gridMesh(3, 3, 1.5, 1.5, ShapeFamily::Gimp));
}

}  // namespace
}  // namespace argine
