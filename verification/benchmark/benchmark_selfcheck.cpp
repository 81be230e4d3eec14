// Hand-computed checks of what the benchmark relies on and of the solver's speed-ups: the
// step profile, the affine element maps and the relocation that uses them, and periodic
// sorting (results equal to round-off, point index of the time-step choice kept). Every
// failed check is reported; the exit code is 1 when any failed.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <iostream>
#include <string>
#include <vector>

#include "BenchmarkScenes.hpp"
#include "VerificationMain.hpp"
#include "argine/mesh/PointLocator.hpp"
#include "argine/meshio/MeshGenerators.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/transfer/AffineElementMaps.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace {

using namespace argine;

int failures = 0;

void expect(const std::string& what, bool ok) {
  if (ok) return;
  std::cout << "FAIL " << what << "\n";
  ++failures;
}

void expectNear(const std::string& what, double value, double expected, double tolerance) {
  if (std::fabs(value - expected) <= tolerance) return;
  std::cout << "FAIL " << what << ": " << value << ", expected " << expected << "\n";
  ++failures;
}

template <class View>
auto host(const View& view) {
  auto copy = Kokkos::create_mirror(Kokkos::HostSpace(), view);
  Kokkos::deep_copy(copy, view);
  return copy;
}

void checkStepProfile() {
  // 3 s of P2G, 1 s of nodal solve, 8 point updates: shares 75 % / 25 %, 8 / 4 = 2 per s.
  StepProfile profile;
  profile.add(StepPhase::P2G, 3.0);
  profile.add(StepPhase::NodalSolve, 1.0);
  profile.point_updates = 8;
  profile.steps = 2;
  expectNear("profile total", profile.total(), 4.0, 1e-15);
  expectNear("profile share", profile.share(StepPhase::P2G), 0.75, 1e-15);
  expectNear("profile rate", profile.pointUpdatesPerSecond(), 2.0, 1e-15);
  const std::string text = profile.describe("");
  expect("profile lists P2G at 75 %",
         text.find("P2G") != std::string::npos && text.find("75.0 %") != std::string::npos);
  expect("profile leaves out phases without time",
         text.find("sort by element") == std::string::npos);
  profile.reset();
  expectNear("profile reset", profile.total(), 0.0, 0.0);
  {
    PhaseTimer timer(profile, StepPhase::Sort);
    const auto until = std::chrono::steady_clock::now() + std::chrono::milliseconds(2);
    while (std::chrono::steady_clock::now() < until) {
    }
  }
  expect("phase timer charges its phase",
         profile.of(StepPhase::Sort) >= 0.002 && profile.of(StepPhase::Sort) < 1.0);
}

void checkAffineMaps() {
  // Tri3 (0,0), (2,0), (0,1): J = [[2, 0], [0, 1]], J^-1 = [[0.5, 0], [0, 1]], origin node 0.
  const Mesh tri =
      assembleMesh(ElementType::Tri3, {{0, 0}, {2, 0}, {0, 1}}, {{0, 1, 2, -1}}, {0}, {"soil"});
  const AffineElementMaps tri_maps(tri);
  const auto inv = host(tri_maps.inverse_jacobian_e);
  const auto origin = host(tri_maps.origin_e);
  expect("tri3 is affine", host(tri_maps.affine_e)(0) == 1);
  expectNear("tri3 J^-1 00", inv(0, 0), 0.5, 1e-15);
  expectNear("tri3 J^-1 01", inv(0, 1), 0.0, 1e-15);
  expectNear("tri3 J^-1 10", inv(0, 2), 0.0, 1e-15);
  expectNear("tri3 J^-1 11", inv(0, 3), 1.0, 1e-15);
  expectNear("tri3 origin", origin(0, 0) + origin(0, 1), 0.0, 1e-15);
  // Quad4 parallelogram (0,0), (2,0), (3,1), (1,1): x = c + J xi with
  // J = 1/4 [[-0+2+3-1, -0-2+3+1], [0+0+1-1, -0-0+1+1]] = [[1, 0.5], [0, 0.5]], det 0.5,
  // J^-1 = [[1, -1], [0, 2]], c = (1.5, 0.5). Trapezoid (0,0), (2,0), (1.5,1), (0.5,1):
  // bilinear term d_x = (0 - 2 + 1.5 - 0.5)/4 = -0.25, not affine.
  const Mesh quads = assembleMesh(
      ElementType::Quad4, {{0, 0}, {2, 0}, {3, 1}, {1, 1}, {10, 0}, {12, 0}, {11.5, 1}, {10.5, 1}},
      {{0, 1, 2, 3}, {4, 5, 6, 7}}, {0, 0}, {"soil"});
  const AffineElementMaps quad_maps(quads);
  const auto qinv = host(quad_maps.inverse_jacobian_e);
  const auto qorigin = host(quad_maps.origin_e);
  const auto affine = host(quad_maps.affine_e);
  expect("parallelogram is affine", affine(0) == 1);
  expect("trapezoid is not affine", affine(1) == 0);
  expectNear("quad4 J^-1 00", qinv(0, 0), 1.0, 1e-15);
  expectNear("quad4 J^-1 01", qinv(0, 1), -1.0, 1e-15);
  expectNear("quad4 J^-1 10", qinv(0, 2), 0.0, 1e-15);
  expectNear("quad4 J^-1 11", qinv(0, 3), 2.0, 1e-15);
  expectNear("quad4 centre x", qorigin(0, 0), 1.5, 1e-15);
  expectNear("quad4 centre y", qorigin(0, 1), 0.5, 1e-15);
}

/// Relocation with the affine maps gives the elements of the general path and the same local
/// coordinates and shape functions to round-off; it counts points that changed element.
void checkRelocation(ElementType type) {
  const std::string kind = type == ElementType::Quad4 ? "quad4" : "tri3";
  benchmark::Scene scene = benchmark::makeBlockScene("relocation", type, 6, 4, PhaseModel::Dry);
  MaterialPoints& points = scene.points;
  // Move every point by (0.013 p mod 0.07, 0.011 p mod 0.05) m (the soil block has free
  // cells above and to the right): some cross into a neighbour.
  auto position = host(points.position);
  for (int p = 0; p < points.count; ++p) {
    position(p, 0) += std::fmod(0.013 * p, 0.07);
    position(p, 1) += std::fmod(0.011 * p, 0.05);
  }
  position(0, 1) = -1.0;  // below the mesh: lost
  Kokkos::deep_copy(points.position, position);
  const auto element_before = host(points.element);

  MaterialPoints general;
  general.allocate(points.count);
  general.count = points.count;
  Kokkos::deep_copy(general.position, points.position);
  Kokkos::deep_copy(general.element, points.element);
  Kokkos::deep_copy(general.local, points.local);

  const PointLocator locator(scene.mesh);
  const AffineElementMaps maps(scene.mesh);
  PointShapes fast, slow;
  const RelocationCounts counts =
      relocateAndEvaluateShapes(scene.mesh, locator, maps, points, fast);
  const int lost = relocateAndEvaluateShapes(scene.mesh, locator, general, slow);
  expect(kind + " relocation: one point lost", counts.lost == 1 && lost == 1);

  const auto element = host(points.element), element_general = host(general.element);
  const auto local = host(points.local), local_general = host(general.local);
  const auto shape = host(everyPointShape(fast, points)),
             shape_general = host(everyPointShape(slow, general));
  int changed = 0;
  double worst_local = 0, worst_value = 0, worst_gradient = 0;
  for (int p = 0; p < points.count; ++p) {
    if (element(p) != element_before(p)) ++changed;
    expect(kind + " relocation: same element", element(p) == element_general(p));
    if (element(p) < 0) continue;
    for (int d = 0; d < kDim; ++d)
      worst_local = std::max(worst_local, std::fabs(local(p, d) - local_general(p, d)));
    for (int a = 0; a < nodesPerElement(type); ++a) {
      worst_value = std::max(worst_value, std::fabs(shape(p).value[a] - shape_general(p).value[a]));
      for (int d = 0; d < kDim; ++d)  // gradients ~ 1 / 0.1 m
        worst_gradient = std::max(
            worst_gradient, std::fabs(shape(p).gradient[a][d] - shape_general(p).gradient[a][d]));
    }
  }
  // Relocating again from the same positions (as after a sort) changes nothing, bit for bit.
  const RelocationCounts again = relocateAndEvaluateShapes(scene.mesh, locator, maps, points, fast);
  const auto local_again = host(points.local);
  const auto shape_again = host(everyPointShape(fast, points));
  bool same = again.changed_element == 0 && again.lost == 1;
  for (int p = 0; p < points.count; ++p)
    for (int a = 0; a < kMaxElementNodes; ++a)
      same = same && shape_again(p).node[a] == shape(p).node[a] &&
             shape_again(p).value[a] == shape(p).value[a] &&
             shape_again(p).gradient[a][0] == shape(p).gradient[a][0] &&
             shape_again(p).gradient[a][1] == shape(p).gradient[a][1] &&
             (a >= kDim || local_again(p, a) == local(p, a));
  expect(kind + " relocation: relocating again changes nothing", same);
  expect(kind + " relocation: some points changed element", changed > 1);
  expect(kind + " relocation: changed elements counted", counts.changed_element == changed);
  expectNear(kind + " relocation: local coordinates", worst_local, 0.0, 1e-13);
  expectNear(kind + " relocation: shape values", worst_value, 0.0, 1e-13);
  expectNear(kind + " relocation: shape gradients", worst_gradient, 0.0, 1e-11);
}

/// A shuffled block run with and without periodic sorting: the same results to round-off
/// (the P2G sums in another order), points ordered by element after a sort, the time-step
/// choice naming the right point after the permutation.
void checkSorting() {
  auto run = [](int sort_interval, StepProfile& profile, TimeStepChoice& choice,
                bool shuffle = true, bool reproducible = false) {
    benchmark::Scene scene =
        benchmark::makeBlockScene("sorting", ElementType::Quad4, 10, 8, PhaseModel::Saturated);
    if (shuffle) benchmark::shufflePoints(scene.points);
    ExplicitTwoPhaseSolver solver(scene.mesh, scene.points, scene.materials);
    solver.setSortInterval(sort_interval);
    solver.setReproducibleSums(reproducible);
    solver.beginStage(scene.stage);
    for (int k = 0; k < 30; ++k) solver.step(solver.chooseTimeStep().time_step);
    profile = solver.profile();
    choice = solver.diagnostics().time_step_choice;
    return scene.points;
  };
  StepProfile unsorted_profile, sorted_profile;
  TimeStepChoice unsorted_choice, sorted_choice;
  const MaterialPoints unsorted = run(0, unsorted_profile, unsorted_choice);
  const MaterialPoints sorted = run(5, sorted_profile, sorted_choice);
  expect("sorting: six sorts in 30 steps", sorted_profile.sorts == 6);
  expect("sorting: none without an interval", unsorted_profile.sorts == 0);
  expect("sorting: profile counts steps",
         sorted_profile.steps == 30 && sorted_profile.point_updates == 30L * 256);

  const auto element = host(sorted.element);
  bool ordered = true;
  for (int p = 1; p < sorted.count; ++p) ordered = ordered && element(p - 1) <= element(p);
  expect("sorting: points ordered by element after a sort", ordered);

  const auto id_sorted = host(sorted.id), id_unsorted = host(unsorted.id);
  expect("sorting: time-step point follows its id",
         sorted_choice.point >= 0 && id_sorted(sorted_choice.point) == sorted_choice.point_id);
  std::vector<int> unsorted_index(unsorted.count);
  for (int p = 0; p < unsorted.count; ++p) unsorted_index.at(id_unsorted(p)) = p;
  const auto pressure_s = host(sorted.pressure_liquid), pressure_u = host(unsorted.pressure_liquid);
  const auto stress_s = host(sorted.stress_effective), stress_u = host(unsorted.stress_effective);
  double pressure_scale = 0, stress_scale = 0, pressure_diff = 0, stress_diff = 0;
  for (int p = 0; p < sorted.count; ++p) {
    const int q = unsorted_index.at(id_sorted(p));
    pressure_scale = std::max(pressure_scale, std::fabs(pressure_u(q)));
    pressure_diff = std::max(pressure_diff, std::fabs(pressure_s(p) - pressure_u(q)));
    for (int c = 0; c < kStressComponents; ++c) {
      stress_scale = std::max(stress_scale, std::fabs(stress_u(q, c)));
      stress_diff = std::max(stress_diff, std::fabs(stress_s(p, c) - stress_u(q, c)));
    }
  }
  expect("sorting: the block is loaded", pressure_scale > 0 && stress_scale > 0);
  // Round-off amplified by K_L / E ~ 200 over 30 steps: far below 1e-8.
  expectNear("sorting: pressures equal to round-off", pressure_diff / pressure_scale, 0, 1e-8);
  expectNear("sorting: stresses equal to round-off", stress_diff / stress_scale, 0, 1e-8);

  // Reproducible sums: seeded or shuffled, sorted or not, the same results bit for bit.
  const MaterialPoints seeded = run(0, unsorted_profile, unsorted_choice, false, true);
  const MaterialPoints mixed = run(5, sorted_profile, sorted_choice, true, true);
  const auto id_seeded = host(seeded.id), id_mixed = host(mixed.id);
  std::vector<int> seeded_index(seeded.count);
  for (int p = 0; p < seeded.count; ++p) seeded_index.at(id_seeded(p)) = p;
  const auto pressure_a = host(seeded.pressure_liquid), pressure_b = host(mixed.pressure_liquid);
  const auto stress_a = host(seeded.stress_effective), stress_b = host(mixed.stress_effective);
  const auto position_a = host(seeded.position), position_b = host(mixed.position);
  bool identical = seeded.count == mixed.count;
  for (int p = 0; p < mixed.count && identical; ++p) {
    const int q = seeded_index.at(id_mixed(p));
    identical = pressure_b(p) == pressure_a(q) && position_b(p, 0) == position_a(q, 0) &&
                position_b(p, 1) == position_a(q, 1);
    for (int c = 0; c < kStressComponents; ++c)
      identical = identical && stress_b(p, c) == stress_a(q, c);
  }
  expect("reproducible sums: shuffled and sorted = seeded, bit for bit", identical);
}

}  // namespace

int main(int argc, char** argv) {
  return argine::verification::runVerification(argc, argv, [](int, char**) {
    checkStepProfile();
    checkAffineMaps();
    checkRelocation(ElementType::Quad4);
    checkRelocation(ElementType::Tri3);
    checkSorting();
    std::cout << (failures == 0 ? "all benchmark self-checks passed\n"
                                : std::to_string(failures) + " check(s) failed\n");
    return failures == 0 ? 0 : 1;
  });
}
