// [2Phase][Boundary] Infiltration and seepage face on a slope that deforms while the
// condition applies: the conditions follow the CURRENT free boundary every step, the liquid
// volume each reports equals the change of the points' liquid mass to round-off, the rain
// let in is q times the current horizontal projection of the rained sides, and a seepage
// face only ever lets liquid out.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "Harness.hpp"
#include "argine/physics/HydraulicBoundaryStep.hpp"

namespace argine {
namespace {

using test::hostCopy;

/// The staircase slope of HydraulicStep.HeadLoadFollowsADeformingSlope: a 6 x 4 background
/// of 0.5 m quads over [0, 3] x [0, 2], soil in the cells with i >= j. Upper surface: treads
/// (normal (0, 1)) and risers (normal (-1, 0)) up to the top y = 2 for 1.5 < x < 3; its
/// horizontal projection is 3 m (the treads).
bool staircaseElement(int e) {
  return e % 6 >= e / 6;
}

/// The upper surface: free sides inside (0, 3) x (0, 2.5+] away from the base and the
/// mesh's left and right edges (sealed).
ZoneSpec upperSurface() {
  ZoneSpec zone;
  zone.kind = ZoneSpec::Kind::Box;
  zone.lower_left = {0.01, 0.01};
  zone.upper_right = {2.99, 10};
  return zone;
}

/// Fixed base, sealed base and mesh sides: liquid enters or leaves only through the
/// condition under test.
std::vector<BoundarySpec> sealedBox() {
  return {test::solidFixity("base", "bottom", true, true), test::impermeable("base seal", "bottom"),
          test::impermeable("left seal", "left"), test::impermeable("right seal", "right")};
}

/// One copy of `base` per point, each starting at the hydrostatic pressure of a water table
/// at y = table: p_L = rho_L g (table - y) (suction above it). Sets the points' material.
std::vector<MaterialSpec> hydrostaticMaterials(const MaterialSpec& base, Real table,
                                               MaterialPoints& points) {
  std::vector<MaterialSpec> materials;
  const auto x = hostCopy(points.position);
  auto material = Kokkos::create_mirror_view(points.material);
  for (int p = 0; p < points.count; ++p) {
    materials.push_back(base);
    materials.back().name = base.name + " " + std::to_string(p);
    materials.back().initial.liquid_pressure = 1000 * 9.81 * (table - x(p, 1));
    material(p) = p;
  }
  Kokkos::deep_copy(points.material, material);
  return materials;
}

Real liquidMass(const MaterialPoints& points) {
  const auto m = hostCopy(points.mass_liquid);
  Real sum = 0;
  for (int p = 0; p < points.count; ++p) sum += m(p);
  return sum;
}

/// Checks that the condition's sides are free sides of the current boundary inside the zone
/// and that every corrected node lies on one of them. Returns the element list of the
/// sides (to see whether the surface moved).
std::vector<int> checkFollowsCurrentBoundary(const HydraulicConditions& h,
                                             const FreeBoundary& boundary) {
  std::set<std::pair<int, int>> free;
  for (const FreeSide& side : boundary.sides()) free.insert({side.element, side.side});
  std::set<int> nodes;
  std::vector<int> elements;
  for (const FreeSide& side : h.sidesUsed()[0]) {
    EXPECT_TRUE(free.count({side.element, side.side}))
        << "side " << side.side << " of element " << side.element << " is not free now";
    EXPECT_TRUE(zoneContains(makeZone(upperSurface()), side.midpoint(0), side.midpoint(1)));
    nodes.insert(side.a);
    nodes.insert(side.b);
    elements.push_back(side.element);
  }
  const auto corrected = hostCopy(h.corrections().node);
  for (int j = 0; j < h.corrections().count(); ++j)
    EXPECT_TRUE(nodes.count(corrected(j)))
        << "corrected node " << corrected(j) << " is on no current side of the condition";
  return elements;
}

/// What one rain run on the staircase reports (m^3/m, summed over the steps).
struct RainSlopeRun {
  Real storage = 0;    ///< the change of the points' liquid volume
  Real reported = 0;   ///< through the rain condition
  Real all_nodes = 0;  ///< through all nodes
  Real interior = 0;   ///< at the nodes on no side of the free boundary
  Real expected = 0;   ///< q x the rained sides' horizontal projection
  bool surface_moved = false;
};

/// The rain of RainOnADeformingSlope..., `Interior Liquid Balance` point (false) or
/// conservative (true); checks every step that the condition follows the current boundary
/// and applies at every node.
RainSlopeRun rainOnDeformingStaircase(bool conservative) {
  const Real q = 1e-4;
  Mesh mesh = test::rectangleMesh(6, 4, 3.0, 2.0, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh, 0, staircaseElement);
  MaterialSpec silt =
      test::elasticMaterial("silt", PhaseModel::Unsaturated, 3e4, 0.3, 0.4, 1e-3, 8e7);
  silt.retention.model = RetentionModel::Linear;
  silt.retention.linear_slope = 1e-6;
  silt.retention.saturation_max = 1;
  silt.retention.saturation_min = 0;
  std::vector<MaterialSpec> materials = hydrostaticMaterials(silt, 0.0, points);
  initialisePointState(materials, points);
  ExplicitTwoPhaseSolver solver(mesh, points, materials);
  BoundarySpec rain;
  rain.name = "rain";
  rain.kind = BoundaryKind::Infiltration;
  rain.hydraulic.on_zone = true;
  rain.hydraulic.zone = upperSurface();
  rain.hydraulic.series.value = q;
  rain.hydraulic.ponding = true;
  std::vector<BoundarySpec> boundaries = sealedBox();
  boundaries.push_back(rain);
  StageSpec stage =
      test::makeStage("rain", SolverKind::Explicit, 9.81, 0.05, boundaries,
                      {CriterionKind::CflUndrained, CriterionKind::Mieremet,
                       CriterionKind::UnsaturatedLiquid, CriterionKind::Infiltration});
  stage.interior_liquid_conservative = conservative;
  solver.beginStage(stage);
  const Real rho = solver.referenceLiquidDensity();
  const Real initial = liquidMass(points);
  RainSlopeRun run;
  Real previous = 0;
  Real min_projection = 1e30, max_projection = 0;
  std::vector<int> first_sides;
  int steps = 0;
  test::runUntil(solver, 1.0, [&] {
    const Real dt = solver.time() - previous;
    previous = solver.time();
    const HydraulicConditions& h = solver.hydraulicConditions();
    const std::vector<int> elements = checkFollowsCurrentBoundary(h, solver.freeBoundary());
    if (first_sides.empty()) first_sides = elements;
    run.surface_moved = run.surface_moved || elements != first_sides;
    Real projection = 0;
    for (const FreeSide& side : h.sidesUsed()[0]) projection += side.normal[1] * side.length;
    min_projection = std::min(min_projection, projection);
    max_projection = std::max(max_projection, projection);
    run.expected += dt * q * projection;
    run.reported += solver.boundaryFluxVolumes()[0];
    run.all_nodes += solver.boundaryFluxVolumes()[1];
    run.interior += solver.boundaryFluxVolumes()[2];
    const auto applied = hostCopy(h.corrections().applied);
    for (int j = 0; j < h.corrections().count(); ++j) EXPECT_EQ(applied(j), 1);
    ++steps;
  });
  run.storage = (liquidMass(points) - initial) / rho;
  std::printf(
      "[ rain slope, %s ] %d steps, %ld detections, surface moved: %s, projection %.6g..%.6g "
      "m\n  storage %.12g, reported %.12g, all nodes %.12g, inside %.12g, expected q x "
      "projection %.12g m^3/m (rel. diff %.3g)\n",
      conservative ? "conservative" : "point", steps, solver.freeBoundary().detections(),
      run.surface_moved ? "yes" : "no", min_projection, max_projection, run.storage, run.reported,
      run.all_nodes, run.interior, run.expected, run.reported / run.expected - 1);
  return run;
}

TEST(HydraulicMovingSurface, RainOnADeformingSlopeEntersAsQTimesTheHorizontalProjection) {
  // Unsaturated soft silt (E = 30 kPa, linear SWRC 1e-6 /Pa, hydrostatic suction under a
  // water table at the base: S_L >= 0.98) under gravity: the slope settles, points change
  // element and the free boundary changes while it rains q = 1e-4 m/s (ponding allowed: the
  // correction applies at every node, every step). Rain falls vertically, w^ = (0, -q):
  // through a side of outward normal n and length L it lets in -w^ . n L = q n_y L, i.e. q
  // times the side's horizontal projection (q L on a tread, 0 on a riser). Expected:
  //  - the rain's reported volume = sum_steps dt q sum_{current sides} n_y L to round-off
  //    (= q x 3 m x 1 s = 3e-4 m^3/m: the staircase stays monotone, its treads cover 3 m);
  //    with q on every side (risers too, the former rule) it was q (3 + 2) m x 1 s, and with
  //    the thesis correction n_L w . n (not the flux weight) 16-26 % off on a deforming body;
  //  - the liquid through all nodes = the change of the points' liquid mass to round-off;
  //  - the condition sits on the current free sides of its zone, every step.
  // NOT asserted: rain = storage. It is not: on a deforming body the points no longer fill
  // the elements, the flux weights G_i of interior and sealed nodes are not zero, and the
  // point mass balance gains or loses liquid there (printed; see doc/theory.md Sec. 5.5).
  const RainSlopeRun run = rainOnDeformingStaircase(false);
  EXPECT_TRUE(run.surface_moved);
  EXPECT_NEAR(run.all_nodes, run.storage, 1e-9 * std::fabs(run.storage));  // the identity
  EXPECT_NEAR(run.expected, 3e-4, 1e-12);  // monotone surface: the projection stays 3 m
  EXPECT_NEAR(run.reported, run.expected, 1e-12 * run.expected);  // q x current projection
  // What the rain brings and the points do not keep is lost at nodes no condition owns: a
  // large part of it at the nodes inside the body, whose cells the deforming points no longer
  // fill evenly (G_i != 0 there; doc/theory.md Sec. 5.5, "Limit: a deforming body"). With
  // full cells that part is zero to round-off (HydraulicStep.RainIntoADryColumn...).
  EXPECT_LT(run.interior, -0.1 * (run.reported - run.storage));
}

TEST(HydraulicMovingSurface, ConservativeInteriorBalanceMakesNoLiquidInsideADeformingSlope) {
  // The same rain with `Interior Liquid Balance: conservative` (InteriorLiquidBalance.hpp):
  // the points give back what the point balance makes at the nodes on no side of the free
  // boundary, so
  //  - nothing is made there: the interior column is 0 to round-off (the point run makes
  //    -1.4e-4 of the 3e-4 m^3/m of rain there);
  //  - the identity still holds: the columns, less what was given back, are the points'
  //    actual change (so the shares given back sum to the nodes' masses);
  //  - the rain is unchanged (the condition's nodes are not closed), and the points keep
  //    all of it: the sealed base's and sides' nodes are closed too (the lock holds the
  //    normal part of w only, G_i has a tangential part there), so the rain is the only way
  //    in or out. The point balance keeps 2 % of it (6.1e-6 m^3/m: -1.4e-4 inside, the rest
  //    at the sealed nodes); the interior nodes alone closed kept 48 %.
  const RainSlopeRun run = rainOnDeformingStaircase(true);
  EXPECT_TRUE(run.surface_moved);
  EXPECT_NEAR(run.interior, 0, 1e-9 * run.expected);
  EXPECT_NEAR(run.all_nodes, run.storage, 1e-9 * std::fabs(run.storage));
  EXPECT_NEAR(run.reported, run.expected, 1e-12 * run.expected);
  EXPECT_NEAR(run.storage, run.reported, 1e-9 * run.reported);  // rain = storage
}

TEST(HydraulicMovingSurface, SeepageFaceOfADeformingSlopeOnlyDrains) {
  // Saturated soft mud (E = 30 kPa, k = 1e-3 m/s, K_L = 2 MPa) with a water table at
  // y_w = 1.5 m: p_L = rho_L g (y_w - y) initially (tension above the table: the saturated
  // model keeps S_L = 1). The whole upper surface is a potential seepage face, everything
  // else sealed. Gravity: the slope settles and its surface moves. Expected:
  //  - the face lets liquid out only, every step (reported volume <= 0): below the table the
  //    zero-pressure prediction drains, above it it would suck liquid in, and the correction
  //    closes those nodes (it must apply at some node, or the test proves nothing);
  //  - the liquid through all nodes = the change of the points' liquid mass to round-off
  //    (the face's share is not: see the rain test);
  //  - the face's points below the table (in elements with a face side at the first step)
  //    end with a lower mean p_L than the other points below the table (measured 26 vs 41
  //    kPa; NOT ~0: the self-
  //    weight loads the soft mud faster than it drains, so p_L rises everywhere, and the
  //    face keeps its points near 0 (weakly: the points are not on the face).
  const Real rho_g = 1000 * 9.81, table = 1.5;
  Mesh mesh = test::rectangleMesh(6, 4, 3.0, 2.0, ElementType::Quad4);
  MaterialPoints points = test::seedUniform(mesh, 0, staircaseElement);
  const MaterialSpec mud =
      test::elasticMaterial("mud", PhaseModel::Saturated, 3e4, 0.3, 0.4, 1e-3, 2e6);
  std::vector<MaterialSpec> materials = hydrostaticMaterials(mud, table, points);
  initialisePointState(materials, points);
  ExplicitTwoPhaseSolver solver(mesh, points, materials);
  BoundarySpec face;
  face.name = "face";
  face.kind = BoundaryKind::SeepageFace;
  face.hydraulic.on_zone = true;
  face.hydraulic.zone = upperSurface();
  std::vector<BoundarySpec> boundaries = sealedBox();
  boundaries.push_back(face);
  StageSpec stage = test::makeStage("drain", SolverKind::Explicit, 9.81, 0.05, boundaries,
                                    {CriterionKind::CflUndrained, CriterionKind::Mieremet});
  solver.beginStage(stage);
  const Real rho = solver.referenceLiquidDensity();
  const Real initial = liquidMass(points);

  // the points of the face's elements below the table, by id: their mean |p_L| at the start
  auto faceMeanPressure = [&](const std::set<int>& ids) {
    const auto id = hostCopy(points.id);
    const auto p = hostCopy(points.pressure_liquid);
    Real sum = 0;
    int n = 0;
    for (int k = 0; k < points.count; ++k)
      if (ids.count(id(k))) sum += std::fabs(p(k)), ++n;
    return n ? sum / n : 0.0;
  };

  Real reported = 0, all_nodes = 0, largest_inflow = -1e30, total_out = 0;
  int steps = 0, closing_steps = 0;
  std::vector<int> first_sides;
  bool surface_moved = false;
  std::set<int> face_ids;
  test::runUntil(solver, 1.0, [&] {
    const HydraulicConditions& h = solver.hydraulicConditions();
    const std::vector<int> elements = checkFollowsCurrentBoundary(h, solver.freeBoundary());
    if (first_sides.empty()) {
      first_sides = elements;
      // the face's points below the table (ids), chosen at the first step
      const auto element = hostCopy(points.element);
      const auto x = hostCopy(points.initial_position);
      const auto id = hostCopy(points.id);
      for (int k = 0; k < points.count; ++k)
        for (const int e : elements)
          if (element(k) == e && x(k, 1) < table - 0.25) face_ids.insert(id(k));
    }
    surface_moved = surface_moved || elements != first_sides;
    const Real volume = solver.boundaryFluxVolumes()[0];
    largest_inflow = std::max(largest_inflow, volume);
    total_out += volume;
    reported += volume;
    all_nodes += solver.boundaryFluxVolumes()[1];
    const auto applied = hostCopy(h.corrections().applied);
    int closed = 0;
    for (int j = 0; j < h.corrections().count(); ++j) closed += applied(j);
    if (closed > 0) ++closing_steps;
    ++steps;
  });
  const Real storage = (liquidMass(points) - initial) / rho;
  const Real initial_face_pressure = [&] {
    Real sum = 0;
    int n = 0;
    const auto x = hostCopy(points.initial_position);
    const auto id = hostCopy(points.id);
    for (int k = 0; k < points.count; ++k)
      if (face_ids.count(id(k))) sum += rho_g * (table - x(k, 1)), ++n;
    return n ? sum / n : 0.0;
  }();
  const Real final_face_pressure = faceMeanPressure(face_ids);
  std::set<int> other_ids;  // the other points below the table
  {
    const auto x = hostCopy(points.initial_position);
    const auto id = hostCopy(points.id);
    for (int k = 0; k < points.count; ++k)
      if (!face_ids.count(id(k)) && x(k, 1) < table - 0.25) other_ids.insert(id(k));
  }
  const Real final_other_pressure = faceMeanPressure(other_ids);
  std::printf(
      "[ seepage slope ] %d steps (%d with closed nodes), surface moved: %s\n"
      "  storage %.12g, reported %.12g, all nodes %.12g m^3/m, largest step volume %.3g\n"
      "  face points below the table (%zu): mean |p_L| %.6g Pa at start -> %.6g Pa; the "
      "other points below it (%zu): %.6g Pa\n",
      steps, closing_steps, surface_moved ? "yes" : "no", storage, reported, all_nodes,
      largest_inflow, face_ids.size(), initial_face_pressure, final_face_pressure, other_ids.size(),
      final_other_pressure);
  EXPECT_TRUE(surface_moved);
  EXPECT_GT(closing_steps, 0);     // the inflow switch was exercised
  EXPECT_LE(largest_inflow, 0.0);  // outflow only, every step
  EXPECT_LT(total_out, 0.0);       // and it drains
  EXPECT_NEAR(all_nodes, storage, 1e-9 * std::fabs(storage));
  EXPECT_FALSE(face_ids.empty());
  EXPECT_LT(final_face_pressure, final_other_pressure);
}

}  // namespace
}  // namespace argine
