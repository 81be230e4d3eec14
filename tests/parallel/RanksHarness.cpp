#include "RanksHarness.hpp"

#include <gtest/gtest.h>
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>

#include "../physics/Harness.hpp"
#include "argine/init/Initialisation.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/parallel/RankDecomposition.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/points/PointFields.hpp"
#include "argine/simulation/MaterialChanges.hpp"
#include "argine/simulation/Setup.hpp"

namespace argine::test {

namespace {

/// The point states of all ranks, by id: kComparedValues per point.
std::vector<Real> gatherById(const MaterialPoints& points, MPI_Comm comm, int total) {
  std::vector<Real> mine;
  for (int p = 0; p < points.count; ++p) {
    mine.insert(mine.end(), {static_cast<Real>(points.id(p)), points.position(p, 0),
                             points.position(p, 1), points.velocity_solid(p, 0),
                             points.velocity_solid(p, 1), points.pressure_liquid(p),
                             points.stress_effective(p, XX), points.stress_effective(p, YY),
                             points.stress_effective(p, XY), points.mass_liquid(p)});
  }
  int size = 1;
  MPI_Comm_size(comm, &size);
  int n = static_cast<int>(mine.size());
  std::vector<int> counts(size), offsets(size + 1, 0);
  MPI_Allgather(&n, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  for (int r = 0; r < size; ++r) offsets[r + 1] = offsets[r] + counts[r];
  std::vector<Real> all(offsets[size]);
  MPI_Allgatherv(mine.data(), n, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                 comm);
  std::vector<Real> by_id(static_cast<std::size_t>(total) * kComparedValues,
                          std::numeric_limits<Real>::quiet_NaN());
  for (std::size_t k = 0; k < all.size(); k += kComparedValues + 1) {
    const int id = static_cast<int>(all[k]);
    for (int v = 0; v < kComparedValues; ++v) by_id[id * kComparedValues + v] = all[k + 1 + v];
  }
  return by_id;
}

}  // namespace

MaterialPoints copyOf(const MaterialPoints& points) {
  MaterialPoints copy;
  copy.allocate(points.count);
#define ARGINE_COPY_FIELD(name) Kokkos::deep_copy(copy.name, points.name);
  ARGINE_MATERIAL_POINT_FIELDS(ARGINE_COPY_FIELD)
#undef ARGINE_COPY_FIELD
  return copy;
}

RanksRun runScene(const RanksScene& scene, bool distributed) {
  MaterialPoints copy = copyOf(scene.points);  // the solver works on a deep copy
  const int total = copy.count;
  ExplicitTwoPhaseSolver solver(scene.mesh, copy, scene.materials);
  solver.setSortInterval(ExplicitTwoPhaseSolver::kRecommendedSortInterval);
  solver.setReproducibleSums(scene.reproducible_sums);
  std::unique_ptr<RankDecomposition> ranks;
  if (distributed) {
    ranks = std::make_unique<RankDecomposition>(
        MPI_COMM_WORLD, scene.mesh,
        scene.weights.empty() ? pointsPerElementWeights(scene.mesh, copy) : scene.weights);
    solver.distribute(*ranks);
  }
  RanksRun result;
  for (const StageSpec& stage : scene.stages) {
    solver.beginStage(stage);
    for (int k = 0; k < scene.steps_per_stage; ++k) {
      solver.step(solver.chooseTimeStep().time_step);
      ++result.steps;
    }
  }
  result.states = gatherById(copy, distributed ? MPI_COMM_WORLD : MPI_COMM_SELF, total);
  result.migrated = solver.migratedPoints();
  return result;
}

std::vector<Real> relativeDifferences(const std::vector<Real>& one, const std::vector<Real>& all,
                                      Real pressure_scale) {
  const int group[kComparedValues] = {0, 0, 1, 1, 2, 3, 3, 3, 4};
  std::vector<Real> scale{0, 0, pressure_scale, 0, 0}, difference(kComparedValues, 0);
  const std::size_t points = one.size() / kComparedValues;
  for (std::size_t p = 0; p < points; ++p)
    for (int v = 0; v < kComparedValues; ++v) {
      const std::size_t k = p * kComparedValues + v;
      scale[group[v]] = std::max(scale[group[v]], std::abs(one[k]));
      const Real d = std::abs(one[k] - all[k]);
      difference[v] =
          std::isnan(d) ? std::numeric_limits<Real>::infinity() : std::max(difference[v], d);
    }
  for (int v = 0; v < kComparedValues; ++v)
    difference[v] /= scale[group[v]] > 0 ? scale[group[v]] : 1;
  return difference;
}

void expectSameAsOneRank(const RanksScene& scene, Real tolerance, long long* migrated) {
  const RanksRun one = runScene(scene, false);
  const RanksRun all = runScene(scene, true);
  const auto difference = relativeDifferences(one.states, all.states, scene.pressure_scale);
  const char* names[kComparedValues] = {"x",    "y",    "v_x",  "v_y", "p_L",
                                        "s_xx", "s_yy", "s_xy", "M_L"};
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  for (int v = 0; v < kComparedValues; ++v) {
    EXPECT_LE(difference[v], tolerance) << names[v];
    if (rank == 0) std::printf("  %s: largest difference / range %.3g\n", names[v], difference[v]);
  }
  if (migrated) *migrated = all.migrated;
}

void expectSameAsOneRankWithMigration(const RanksScene& scene, Real tolerance) {
  long long migrated = 0;
  expectSameAsOneRank(scene, tolerance, &migrated);
  int size = 1, rank = 0;
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (size > 1) {
    EXPECT_GT(migrated, 0) << "no point crossed the rank border";
  }
  if (rank == 0) std::printf("  points moved between ranks: %lld\n", migrated);
}

RanksScene deckScene(const std::string& relative_path, int first, int count, int steps) {
  const Deck deck = readDeck(std::string(ARGINE_SOURCE_DIR) + "/" + relative_path);
  RanksScene scene;
  scene.mesh = loadMesh(deck);
  scene.points = seedPoints(deck, scene.mesh);
  initialisePoints(deck, scene.mesh, scene.points);
  scene.materials = deck.materials;
  for (int s = first; s < first + count && s < static_cast<int>(deck.stages.size()); ++s) {
    scene.stages.push_back(deck.stages[s]);
    applyMaterialChanges(deck.stages[s].name, deck.stages[s].material_changes, scene.materials);
  }
  scene.steps_per_stage = steps;
  return scene;
}

RanksScene slumpingSlope(Real damping) {
  RanksScene scene;
  scene.mesh = rectangleMesh(16, 6, 2.0, 0.75, ElementType::Quad4);
  scene.points = seedUniform(scene.mesh, 0, [](int e) { return e % 16 < 8 && e / 16 < 5; });
  MaterialSpec soil = elasticMaterial("soil", PhaseModel::Saturated, 5e6, 0.3, 0.4, 1e-2, 2.2e6);
  soil.solid.model = SolidModel::MohrCoulomb;
  soil.solid.cohesion = 0;
  soil.solid.friction_angle = 25 * M_PI / 180;
  scene.materials = {soil};
  initialisePointState(scene.materials, scene.points);
  StageSpec slump = makeStage(
      "slump", SolverKind::Explicit, kStandardGravity, 0.0,
      {solidFixity("base", "bottom", true, true), solidFixity("wall", "left", true, false)});
  slump.local_damping = damping;
  // open (the thesis' natural p_L = 0 on the free sides): with the atmosphere no water
  // enters the saturated block where it unloads, its p_L falls without bound (the saturated
  // model has no air entry) and the c' = 0 block stands on that suction instead of slumping
  slump.atmosphere_on_free_surfaces = false;
  scene.stages = {slump};
  scene.steps_per_stage = 700;
  scene.weights.assign(scene.mesh.numElements(), 1.0);
  return scene;
}

}  // namespace argine::test
