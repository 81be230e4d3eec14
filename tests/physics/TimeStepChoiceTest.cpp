// TimeStepControl::evaluate against the rule of its header, computed point by point on the
// host: the smallest critical step over the located points in order and, per point, over
// the stage's criteria in order (the first of equal ones); dry points the dry CFL alone.

#include <gtest/gtest.h>

#include <limits>
#include <random>

#include "Harness.hpp"
#include "argine/mesh/MeshGeometry.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/TimeStepControl.hpp"
#include "argine/timestep/Criteria.hpp"

namespace argine {
namespace {

struct Expected {
  Real step = std::numeric_limits<Real>::max();
  int point = -1;
  CriterionKind governing = CriterionKind::CflDry;
};

/// The header's rule, one point and one criterion at a time.
Expected smallestStep(const MaterialPoints& points, const MaterialTable& table, const Mesh& mesh,
                      const std::vector<CriterionKind>& criteria, Real mass_scaling) {
  const auto size = test::hostCopy(elementCharacteristicSizes(mesh));
  const auto element = test::hostCopy(points.element), material = test::hostCopy(points.material);
  const auto n = test::hostCopy(points.porosity), s = test::hostCopy(points.saturation);
  const auto rho = test::hostCopy(points.density_liquid), k = test::hostCopy(points.conductivity);
  const auto p_l = test::hostCopy(points.pressure_liquid);
  Expected best;
  for (int p = 0; p < points.count; ++p) {
    if (element(p) < 0) continue;
    const PointMaterial& m = table.host(material(p));
    CriterionInput in;
    in.element_size = size(element(p));
    in.porosity = n(p);
    in.solid_density = m.solid_density;
    in.liquid_bulk_modulus = m.liquid.bulk_modulus;
    in.constrained_modulus = m.constrained_modulus;
    in.mass_scaling = mass_scaling;
    in.saturation = s(p);
    in.saturation_suction_derivative =
        m.phase == PhaseModel::Unsaturated
            ? saturationSuctionDerivative(m.retention, suctionOfPressure(p_l(p)))
            : 0;
    in.liquid_density = rho(p);
    in.hydraulic_conductivity = k(p);
    const bool wet = carriesLiquid(m.phase);
    for (std::size_t c = 0; c < (wet ? criteria.size() : 1); ++c) {
      const CriterionKind kind = wet ? criteria[c] : CriterionKind::CflDry;
      const Real dt = criticalStep(kind, in);
      if (dt < best.step) best = Expected{dt, p, kind};
    }
  }
  return best;
}

TEST(TimeStepControl, ChoosesTheFirstSmallestStepOverPointsAndCriteria) {
  // Dry, saturated and unsaturated (linear SWRC) points mixed in one column, with scattered
  // porosity, saturation, density and conductivity, and one point outside the mesh.
  MaterialSpec dry = test::elasticMaterial("dry", PhaseModel::Dry, 2e7, 0.3, 0.35);
  MaterialSpec wet = test::elasticMaterial("wet", PhaseModel::Saturated, 1e7, 0.3, 0.4, 1e-5);
  MaterialSpec silt = test::elasticMaterial("silt", PhaseModel::Unsaturated, 5e6, 0.25, 0.3);
  silt.retention.model = RetentionModel::Linear;
  silt.retention.linear_slope = 1e-6;
  silt.retention.saturation_max = 1;
  silt.retention.saturation_min = 0;
  test::Column column(12, 0.1, 1.2, wet);
  const std::vector<MaterialSpec> materials{dry, wet, silt};
  const MaterialTable table(materials);
  MaterialPoints& points = column.points;
  std::mt19937 random(7);
  std::uniform_real_distribution<Real> unit(0, 1);
  auto material = test::hostCopy(points.material), element = test::hostCopy(points.element);
  auto n = test::hostCopy(points.porosity), s = test::hostCopy(points.saturation);
  auto rho = test::hostCopy(points.density_liquid), k = test::hostCopy(points.conductivity);
  auto p_l = test::hostCopy(points.pressure_liquid);
  for (int p = 0; p < points.count; ++p) {
    material(p) = p % 3;
    n(p) = 0.25 + 0.2 * unit(random);
    s(p) = material(p) == 2 ? 0.4 + 0.6 * unit(random) : 1;
    rho(p) = 995 + 10 * unit(random);
    k(p) = std::pow(10.0, -7 + 3 * unit(random));
    p_l(p) = material(p) == 2 ? -1e5 * unit(random) : 1e4 * unit(random);
  }
  element(5) = -1;  // lost: not taken
  for (auto [host, view] :
       {std::pair{n, points.porosity}, std::pair{s, points.saturation},
        std::pair{rho, points.density_liquid}, std::pair{k, points.conductivity},
        std::pair{p_l, points.pressure_liquid}})
    Kokkos::deep_copy(view, host);
  Kokkos::deep_copy(points.material, material);
  Kokkos::deep_copy(points.element, element);

  TimeStepControl control(column.mesh);
  for (const std::vector<CriterionKind>& criteria :
       {std::vector<CriterionKind>{CriterionKind::MieremetLiquidDrag, CriterionKind::Consolidation},
        std::vector<CriterionKind>{CriterionKind::CflUndrained, CriterionKind::Infiltration,
                                   CriterionKind::UnsaturatedCoupled, CriterionKind::Mieremet},
        std::vector<CriterionKind>{CriterionKind::Consolidation, CriterionKind::Consolidation}}) {
    for (const Real scaling : {1.0, 100.0}) {
      TimeStepSpec spec;
      spec.criteria = criteria;
      control.configure(spec, scaling, "s");
      const TimeStepChoice choice = control.evaluate(points, table);
      const Expected expected = smallestStep(points, table, column.mesh, criteria, scaling);
      ASSERT_GE(expected.point, 0);
      EXPECT_EQ(choice.critical_step, expected.step);  // the same expressions: the same bits
      EXPECT_EQ(choice.point, expected.point);
      EXPECT_EQ(choice.governing, expected.governing);
    }
  }
  // Only dry points located: the dry CFL governs whatever the stage selected.
  for (int p = 0; p < points.count; ++p) element(p) = material(p) == 0 ? 0 : -1;
  Kokkos::deep_copy(points.element, element);
  TimeStepSpec spec;
  spec.criteria = {CriterionKind::Mieremet};
  control.configure(spec, 1, "s");
  const TimeStepChoice choice = control.evaluate(points, table);
  const Expected expected = smallestStep(points, table, column.mesh, {CriterionKind::Mieremet}, 1);
  EXPECT_EQ(choice.governing, CriterionKind::CflDry);
  EXPECT_EQ(choice.point, expected.point);
  EXPECT_EQ(choice.critical_step, expected.step);

  // Only saturated points: the two Mieremet criteria give equal steps (S_L = 1), and the
  // one listed first governs.
  for (int p = 0; p < points.count; ++p) {
    element(p) = 0;
    material(p) = 1;
    s(p) = 1;
  }
  Kokkos::deep_copy(points.element, element);
  Kokkos::deep_copy(points.material, material);
  Kokkos::deep_copy(points.saturation, s);
  for (const CriterionKind first : {CriterionKind::Mieremet, CriterionKind::MieremetLiquidDrag}) {
    const CriterionKind second = first == CriterionKind::Mieremet
                                     ? CriterionKind::MieremetLiquidDrag
                                     : CriterionKind::Mieremet;
    spec.criteria = {first, second};
    control.configure(spec, 1, "s");
    const TimeStepChoice tie = control.evaluate(points, table);
    const Expected expected_tie = smallestStep(points, table, column.mesh, spec.criteria, 1);
    EXPECT_EQ(tie.critical_step, expected_tie.step);
    EXPECT_EQ(tie.point, expected_tie.point);
    EXPECT_EQ(tie.governing, first);
  }
}

}  // namespace
}  // namespace argine
