// The volumetric averaging's increments (physics/VolumetricAveraging.hpp) when every point
// averages its three channels over nodes (the levee decks): the shared-weight kernels give
// what averagePointValues gives for the three channels with a weight column each, followed
// by the put-back of averageStrainIncrements, bit for bit, on Tri3 and Quad4 meshes with
// unequal volumes, a dry material without averaging beside the soil and a lost point.

#include <gtest/gtest.h>

#include <cmath>

#include "../transfer/TestScenes.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/physics/VolumetricAveraging.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {
namespace {

using test::hostCopy;

/// Fills the increments with values that differ from point to point and from each other.
void setIncrements(PointRates& rates, int count) {
  auto strain = Kokkos::create_mirror_view(rates.strain_increment_p);
  auto divergence = Kokkos::create_mirror_view(rates.liquid_divergence_increment_p);
  auto flux = Kokkos::create_mirror_view(rates.content_flux_divergence_increment_p);
  for (int p = 0; p < count; ++p) {
    for (int k = 0; k < kStressComponents; ++k) strain(p, k) = 1e-4 * std::sin(1.0 + p + 3 * k);
    divergence(p) = 2e-4 * std::cos(0.5 + 2 * p);
    flux(p) = 3e-2 * std::sin(0.3 * p * p);
  }
  Kokkos::deep_copy(rates.strain_increment_p, strain);
  Kokkos::deep_copy(rates.liquid_divergence_increment_p, divergence);
  Kokkos::deep_copy(rates.content_flux_divergence_increment_p, flux);
}

/// The increments as averagePointValues and averageStrainIncrements' put-back make them: one
/// channel a weight column, material 0 nodal on a liquid-carrying phase, material 1 none.
void expectedIncrements(const MaterialPoints& points, const PointShapes& shapes,
                        const ActiveNodes& active, int nodes, PointRates& rates) {
  AveragingScratch scratch;
  AveragingUse use;
  use.add(kAverageNodal);
  scratch.allocateSums(3, use, 0, nodes);
  scratch.fitPoints(points.count);
  auto mode = Kokkos::create_mirror_view(scratch.mode_pc);
  auto value = Kokkos::create_mirror_view(scratch.value_pc);
  auto weight = Kokkos::create_mirror_view(scratch.weight_p);
  auto strain = hostCopy(rates.strain_increment_p);
  auto divergence = hostCopy(rates.liquid_divergence_increment_p);
  auto flux = hostCopy(rates.content_flux_divergence_increment_p);
  const auto material = hostCopy(points.material);
  const auto volume = hostCopy(points.volume);
  const auto element = hostCopy(points.element);
  for (int p = 0; p < points.count; ++p) {
    const int m = material(p) == 0 ? kAverageNodal : kAverageNone;
    const Real eps = strain(p, XX) + strain(p, YY);
    weight(p) = volume(p);
    for (int c = 0; c < 3; ++c) mode(p, c) = m;
    value(p, 0) = flux(p);
    value(p, 1) = divergence(p) - eps;
    value(p, 2) = eps;
  }
  Kokkos::deep_copy(scratch.mode_pc, mode);
  Kokkos::deep_copy(scratch.value_pc, value);
  Kokkos::deep_copy(scratch.weight_p, weight);
  averagePointValues(points, shapes, active, scratch, nullptr);
  Kokkos::deep_copy(value, scratch.value_pc);
  for (int p = 0; p < points.count; ++p) {
    if (element(p) < 0 || mode(p, 0) == kAverageNone) continue;
    flux(p) = value(p, 0);
    const Real shift = value(p, 2) - (strain(p, XX) + strain(p, YY));
    strain(p, XX) += shift / 2;
    strain(p, YY) += shift / 2;
    divergence(p) = value(p, 1) + value(p, 2);
  }
  Kokkos::deep_copy(rates.strain_increment_p, strain);
  Kokkos::deep_copy(rates.liquid_divergence_increment_p, divergence);
  Kokkos::deep_copy(rates.content_flux_divergence_increment_p, flux);
}

void expectSharedWeightKernelsAsGeneric(ElementType type) {
  const Mesh mesh = test::rectangleMesh(3, 2, 1.5, 1.0, type);
  MaterialPoints points = test::seedUniform(mesh);
  {  // unequal volumes, every fifth point dry (material 1), the last point lost
    auto volume = Kokkos::create_mirror_view(points.volume);
    auto material = Kokkos::create_mirror_view(points.material);
    auto element = Kokkos::create_mirror_view(points.element);
    Kokkos::deep_copy(volume, points.volume);
    Kokkos::deep_copy(element, points.element);
    for (int p = 0; p < points.count; ++p) {
      volume(p) *= 1 + 0.1 * std::sin(2.0 * p);
      material(p) = p % 5 == 4 ? 1 : 0;
    }
    element(points.count - 1) = -1;
    Kokkos::deep_copy(points.volume, volume);
    Kokkos::deep_copy(points.material, material);
    Kokkos::deep_copy(points.element, element);
  }
  MaterialSpec soil = test::elasticMaterial("soil", PhaseModel::Unsaturated, 5e7, 0.3, 0.4);
  soil.locking.volumetric_strain = IncrementAveraging::Nodal;
  const MaterialSpec dry = test::elasticMaterial("dry", PhaseModel::Dry, 5e7, 0.3, 0.4);
  const MaterialTable table({soil, dry});
  PointShapes shapes;
  evaluatePointShapes(mesh, points, shapes);
  ActiveNodes active{mesh.numNodes()};
  active.rebuild(mesh, points);

  PointRates fused, generic;
  fused.allocate(points.count);
  generic.allocate(points.count);
  setIncrements(fused, points.count);
  setIncrements(generic, points.count);
  VolumetricAveraging averaging(table, mesh);
  averaging.averageStrainIncrements(table, points, shapes, active, fused);
  expectedIncrements(points, shapes, active, mesh.numNodes(), generic);

  const auto strain = hostCopy(fused.strain_increment_p);
  const auto strain_expected = hostCopy(generic.strain_increment_p);
  const auto divergence = hostCopy(fused.liquid_divergence_increment_p);
  const auto divergence_expected = hostCopy(generic.liquid_divergence_increment_p);
  const auto flux = hostCopy(fused.content_flux_divergence_increment_p);
  const auto flux_expected = hostCopy(generic.content_flux_divergence_increment_p);
  int changed = 0;
  PointRates untouched;
  untouched.allocate(points.count);
  setIncrements(untouched, points.count);
  const auto strain_before = hostCopy(untouched.strain_increment_p);
  for (int p = 0; p < points.count; ++p) {
    for (int k = 0; k < kStressComponents; ++k)
      EXPECT_EQ(strain(p, k), strain_expected(p, k)) << "point " << p << " component " << k;
    EXPECT_EQ(divergence(p), divergence_expected(p)) << "point " << p;
    EXPECT_EQ(flux(p), flux_expected(p)) << "point " << p;
    if (strain(p, XX) != strain_before(p, XX)) ++changed;
  }
  // the averaging did something: all located soil points changed, the dry ones did not
  EXPECT_GT(changed, points.count / 2);
}

TEST(VolumetricAveraging, SharedWeightNodalChannelsEqualTheGenericAveragingOnTri3) {
  expectSharedWeightKernelsAsGeneric(ElementType::Tri3);
}

TEST(VolumetricAveraging, SharedWeightNodalChannelsEqualTheGenericAveragingOnQuad4) {
  expectSharedWeightKernelsAsGeneric(ElementType::Quad4);
}

}  // namespace
}  // namespace argine
