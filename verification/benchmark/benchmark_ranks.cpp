/// @file benchmark_ranks.cpp
/// argine_benchmark_ranks: throughput of the explicit two-phase step over MPI ranks (issue P7).
/// Run under `mpiexec -n N`. For each scene it runs the steps first on rank 0 alone (the
/// other ranks wait without spinning), then on all N ranks (RankDecomposition, the same
/// scene), and prints the material-point updates per second PER RANK of both runs, the
/// speed-up and the parallel efficiency = per-rank rate on N ranks / rate on one rank, the
/// point balance, the nodal exchange traffic per step and the points migrated.
///
///   mpiexec -n 2 argine_benchmark_ranks [--scenes levee_drawdown,block-1e6] [--steps N]
///                                       [--warmup 5] [--repeat 3] [--reproducible-sums]
///
/// Scenes: levee_drawdown = the 'drawdown' stage of inputs/levee_drawdown (Mohr-Coulomb,
/// unsaturated, total head with a seepage face; 2,757 points) from its K0 state, 400 steps;
/// levee_drawdown@H = the same with `Element Size (m): H` (e.g. @0.05: 44,481 points, the
/// finest mesh of the convergence study), at least 1.1e6 point updates and 100 steps a
/// repeat; any other deck of inputs/levee_drawdown by its name, with or without @H (e.g.
/// levee_drawdown_grid_conjugate@0.05: uGIMP, APIC, the run-out study's grid levee), the same way;
/// block-1e6 = a saturated Mohr-Coulomb block of 500 x 500 quads, 4 points each (1,000,000
/// points) in a 520 x 520 mesh, 10 steps; any scene of argine_benchmark (BenchmarkScenes.hpp,
/// ~1e5 points), 50 steps; "schemes" = the Mohr-Coulomb block on each shape family and
/// velocity transfer. --reproducible-sums: the deck's `Parallel: {Reproducible Sums: true}`,
/// with which the fingerprints of 1 and N ranks must be equal (else exit 1). With several
/// scenes a closing table lists the rates and whether the fingerprints agree. Speed is never
/// judged: exit 0 when the rates are finite and positive.

#include <mpi.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "BenchmarkScenes.hpp"
#include "CommandLine.hpp"
#include "PointFingerprint.hpp"
#include "VerificationMain.hpp"
#include "argine/init/Initialisation.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/parallel/RankDecomposition.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/points/PointFields.hpp"
#include "argine/simulation/MaterialChanges.hpp"
#include "argine/simulation/Setup.hpp"

namespace argine::benchmark {
namespace {

struct Problem {
  std::string name;
  Mesh mesh;
  MaterialPoints points;
  std::vector<MaterialSpec> materials;
  StageSpec stage;
  int steps = 10;
};

/// The file of a deck of inputs/levee_drawdown, by its name without .yaml.
std::string leveeDeckPath(const std::string& deck_name) {
  return std::string(ARGINE_SOURCE_DIR) + "/inputs/levee_drawdown/" + deck_name + ".yaml";
}

/// A levee scene: `deck` (a deck of inputs/levee_drawdown, e.g. levee_drawdown or
/// levee_drawdown_grid_conjugate) on its own mesh, or with `Element Size (m)` set to
/// element_size (> 0): the same scene refined as scripts/convergence.sh refines it, for the
/// step's rate per point at the resolutions of the convergence study (levee_drawdown on
/// 0.05 m: 44,481 points). Its second stage (the drawdown) from the K0 state. The shipped
/// levee_drawdown deck on its own mesh keeps 400 steps, so its fingerprint compares across
/// builds; any other takes at least 1.1e6 point updates and 100 steps a repeat (fewer steps
/// weigh the set-up of a repeat, a fresh copy of the points, too much: 24 steps of the 0.05 m
/// mesh read a third slower per point than 100).
Problem leveeScene(const std::string& name, const std::string& deck_name, Real element_size) {
  Deck deck = readDeck(leveeDeckPath(deck_name));
  if (element_size > 0) deck.mesh.generator.element_size = element_size;
  Problem problem;
  problem.name = name;
  problem.mesh = loadMesh(deck);
  problem.points = seedPoints(deck, problem.mesh);
  initialisePoints(deck, problem.mesh, problem.points);
  problem.materials = deck.materials;
  problem.stage = deck.stages.at(1);
  applyMaterialChanges(problem.stage.name, problem.stage.material_changes, problem.materials);
  problem.steps = element_size == 0 && deck_name == "levee_drawdown"
                      ? 400
                      : std::max(100, static_cast<int>(1.1e6 / problem.points.count));
  return problem;
}

constexpr const char* kLeveeDrawdown = "levee_drawdown";

/// A levee scene's name split: "DECK" or "DECK@H" (DECK a deck of inputs/levee_drawdown
/// without .yaml, H in m; 0 for DECK's own mesh); std::invalid_argument for a deck that is not
/// there or an H that is not a positive number.
struct LeveeSceneName {
  std::string deck;
  Real element_size = 0;
};

LeveeSceneName parseLeveeScene(const std::string& name) {
  const std::size_t at = name.find('@');
  LeveeSceneName parsed{name.substr(0, at), 0};
  const std::string expected =
      "benchmark scene '" + name +
      "': expected DECK or DECK@H, DECK a deck of inputs/levee_drawdown without .yaml and H an "
      "element size > 0 in m, e.g. levee_drawdown@0.05 or levee_drawdown_grid_conjugate@0.05";
  if (parsed.deck.find('/') != std::string::npos || !std::ifstream(leveeDeckPath(parsed.deck)))
    throw std::invalid_argument(expected);
  if (at == std::string::npos) return parsed;
  const std::string text = name.substr(at + 1);
  char* end = nullptr;
  const double size = std::strtod(text.c_str(), &end);
  if (text.empty() || end != text.c_str() + text.size() || !(size > 0) || !std::isfinite(size))
    throw std::invalid_argument(expected);
  parsed.element_size = size;
  return parsed;
}

/// A scene of argine_benchmark (BenchmarkScenes.hpp).
Problem benchmarkScene(const std::string& name) {
  Scene scene = makeScene(name);
  Problem problem;
  problem.name = name;
  problem.mesh = scene.mesh;
  problem.points = scene.points;
  problem.materials = scene.materials;
  problem.stage = scene.stage;
  problem.steps = 50;
  return problem;
}

Problem millionPointBlock() {
  Scene scene = makeBlockScene("block-1e6", ElementType::Quad4, 520, 500, PhaseModel::Saturated);
  Problem problem;
  problem.name = "block-1e6";
  problem.mesh = scene.mesh;
  problem.points = scene.points;
  problem.materials = scene.materials;
  for (auto& material : problem.materials) {  // the P7 goal is for Mohr-Coulomb
    material.solid.model = SolidModel::MohrCoulomb;
    material.solid.cohesion = 20e3;
    material.solid.friction_angle = 30 * M_PI / 180;
    material.solid.dilatancy_angle = 0;
  }
  problem.stage = scene.stage;
  problem.steps = 10;
  return problem;
}

MaterialPoints deepCopy(const MaterialPoints& points) {
  MaterialPoints copy;
  copy.allocate(points.count);
#define ARGINE_COPY_FIELD(name) Kokkos::deep_copy(copy.name, points.name);
  ARGINE_MATERIAL_POINT_FIELDS(ARGINE_COPY_FIELD)
#undef ARGINE_COPY_FIELD
  return copy;
}

/// Waits at a barrier of `comm` without spinning a core (the other ranks' run is timed).
void quietBarrier(MPI_Comm comm) {
  MPI_Request request;
  MPI_Ibarrier(comm, &request);
  int done = 0;
  while (!done) {
    MPI_Test(&request, &done, MPI_STATUS_IGNORE);
    if (!done) usleep(2000);
  }
}

struct Timing {
  double wall = 0;                     ///< median wall time of the timed steps (s)
  double cpu = 0;                      ///< its process CPU time (s)
  long long points = 0;                ///< this rank's points at the end
  StepProfile profile;                 ///< of the median repeat
  long long exchange_bytes = 0;        ///< nodal exchange bytes this rank sent per step
  long long migrated = 0;              ///< points moved between ranks in all steps
  unsigned long long fingerprint = 0;  ///< additiveFingerprint of the final state, all ranks
};

/// How the steps are run and timed.
struct Settings {
  int warmup = 5;
  int repeat = 3;
  bool reproducible_sums = false;
};

Timing timeSteps(const Problem& problem, MPI_Comm comm, bool distributed,
                 const Settings& settings) {
  const int warmup = settings.warmup, repeat = settings.repeat;
  MaterialPoints points = deepCopy(problem.points);
  ExplicitTwoPhaseSolver solver(problem.mesh, points, problem.materials);
  solver.setSortInterval(ExplicitTwoPhaseSolver::kRecommendedSortInterval);
  solver.setReproducibleSums(settings.reproducible_sums);
  std::unique_ptr<RankDecomposition> ranks;
  if (distributed) {
    ranks = std::make_unique<RankDecomposition>(comm, problem.mesh,
                                                pointsPerElementWeights(problem.mesh, points));
    solver.distribute(*ranks);
  }
  solver.beginStage(problem.stage);
  for (int k = 0; k < warmup; ++k) solver.step(solver.chooseTimeStep().time_step);
  std::vector<Timing> samples;
  long long bytes_before = solver.exchangeTraffic() ? solver.exchangeTraffic()->bytes : 0;
  for (int r = 0; r < repeat; ++r) {
    MPI_Barrier(comm);
    solver.resetProfile();
    Timing t;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    for (int k = 0; k < problem.steps; ++k) solver.step(solver.chooseTimeStep().time_step);
    MPI_Barrier(comm);
    t.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    t.cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    t.profile = solver.profile();
    samples.push_back(t);
  }
  std::sort(samples.begin(), samples.end(),
            [](const Timing& a, const Timing& b) { return a.wall < b.wall; });
  Timing median = samples[samples.size() / 2];
  median.points = points.count;
  if (solver.exchangeTraffic())
    median.exchange_bytes = (solver.exchangeTraffic()->bytes - bytes_before) /
                            (static_cast<long long>(repeat) * problem.steps);
  median.migrated = solver.migratedPoints();
  median.fingerprint = additiveFingerprint(points);
  MPI_Allreduce(MPI_IN_PLACE, &median.fingerprint, 1, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
  return median;
}

/// What a scene gave, for the closing table (rank 0).
struct ProblemResult {
  std::string name;
  double rate_one = 0;  ///< point updates/s on one rank
  double rate_all = 0;  ///< per rank on all ranks
  bool same_bits = false;
  bool finite = false;
};

ProblemResult runProblem(const Problem& problem, const Settings& settings) {
  const int warmup = settings.warmup, repeat = settings.repeat;
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const double updates = static_cast<double>(problem.points.count) * problem.steps;

  // One rank: rank 0 alone, the others wait quietly.
  Timing one;
  if (rank == 0) one = timeSteps(problem, MPI_COMM_SELF, false, settings);
  quietBarrier(MPI_COMM_WORLD);
  MPI_Bcast(&one.wall, 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);

  const Timing all = timeSteps(problem, MPI_COMM_WORLD, true, settings);
  std::vector<long long> points(size), bytes(size);
  std::vector<double> cpu(size);
  MPI_Gather(&all.points, 1, MPI_LONG_LONG, points.data(), 1, MPI_LONG_LONG, 0, MPI_COMM_WORLD);
  MPI_Gather(&all.exchange_bytes, 1, MPI_LONG_LONG, bytes.data(), 1, MPI_LONG_LONG, 0,
             MPI_COMM_WORLD);
  MPI_Gather(&all.cpu, 1, MPI_DOUBLE, cpu.data(), 1, MPI_DOUBLE, 0, MPI_COMM_WORLD);
  const double rate_one = updates / one.wall;
  const double rate_all = updates / all.wall / size;  // per rank
  if (rank == 0) {
    std::printf(
        "scene %s: %d points, %d elements, %d steps x %d repeats (median) after %d "
        "warm-up steps%s\n",
        problem.name.c_str(), problem.points.count, problem.mesh.numElements(), problem.steps,
        repeat, warmup, settings.reproducible_sums ? ", reproducible sums" : "");
    std::printf("  1 rank : wall %.3f s, %.3g point updates/s (CPU %.3f s, %.3g /s)\n", one.wall,
                rate_one, one.cpu, updates / one.cpu);
    std::printf("  %d ranks: wall %.3f s, %.3g point updates/s PER RANK (%.3g in all)\n", size,
                all.wall, rate_all, rate_all * size);
    std::printf("  speed-up %.2f, parallel efficiency %.0f %% (wall)\n", one.wall / all.wall,
                100 * rate_all / rate_one);
    // On a shared machine the wall time counts the time other jobs held the cores; the
    // process CPU time does not (it does count MPI's busy waiting, so it is conservative).
    const double cpu_max = *std::max_element(cpu.begin(), cpu.end());
    const double cpu_rate_one = updates / one.cpu, cpu_rate_all = updates / cpu_max / size;
    std::printf(
        "  by CPU time: 1 rank %.3g updates/s; %d ranks %.3g updates/s per rank (slowest "
        "rank); speed-up %.2f, efficiency %.0f %%\n",
        cpu_rate_one, size, cpu_rate_all, one.cpu / cpu_max, 100 * cpu_rate_all / cpu_rate_one);
    for (int r = 0; r < size; ++r)
      std::printf(
          "    rank %d: %lld points, CPU %.3f s, nodal exchange %lld bytes sent per "
          "step\n",
          r, points[r], cpu[r], bytes[r]);
    std::printf("  points migrated between ranks: %lld\n", all.migrated);
    // Equal = bit-for-bit the same final states (the last repeat's): between builds, or
    // between 1 and N ranks with reproducible sums (otherwise they differ by round-off).
    std::printf("  final state fingerprint: 1 rank %016llx, %d ranks %016llx\n", one.fingerprint,
                size, all.fingerprint);
    std::printf("  profile, 1 rank:\n%s", one.profile.describe("    ").c_str());
    std::printf("  profile, rank 0 of %d:\n%s\n", size, all.profile.describe("    ").c_str());
    std::fflush(stdout);
  }
  MPI_Bcast(&one.fingerprint, 1, MPI_UNSIGNED_LONG_LONG, 0, MPI_COMM_WORLD);
  ProblemResult result;
  result.name = problem.name;
  result.rate_one = rate_one;
  result.rate_all = rate_all;
  result.same_bits = one.fingerprint == all.fingerprint;
  result.finite =
      std::isfinite(rate_one) && rate_one > 0 && std::isfinite(rate_all) && rate_all > 0;
  return result;
}

void printSummary(const std::vector<ProblemResult>& results, int size) {
  std::printf("%-34s %14s %16s %9s  %s\n", "scene", "1 rank, /s", "per rank (of N)", "speed-up",
              "same bits on 1 and N ranks");
  for (const ProblemResult& r : results)
    std::printf("%-34s %14.3g %16.3g %9.2f  %s\n", r.name.c_str(), r.rate_one, r.rate_all,
                r.rate_all * size / r.rate_one, r.same_bits ? "yes" : "no");
}

/// Mean time of one Allreduce of 8 doubles over MPI_COMM_WORLD (s): the latency each of a
/// step's synchronisations pays at least (on a loaded machine: until both ranks run again).
double allreduceLatency(int repeats) {
  Real values[8] = {0, 0, 0, 0, 0, 0, 0, 0};
  MPI_Barrier(MPI_COMM_WORLD);
  const auto start = std::chrono::steady_clock::now();
  for (int k = 0; k < repeats; ++k)
    MPI_Allreduce(MPI_IN_PLACE, values, 8, MPI_DOUBLE, MPI_SUM, MPI_COMM_WORLD);
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() / repeats;
}

int run(int argc, char** argv) {
  const verification::CommandLine options(
      argc, argv, {"scenes", "steps", "warmup", "repeat", "reproducible-sums"});
  Settings settings;
  settings.warmup = static_cast<int>(options.number("warmup", settings.warmup));
  settings.repeat = std::max(1, static_cast<int>(options.number("repeat", settings.repeat)));
  settings.reproducible_sums = options.has("reproducible-sums");
  const std::vector<std::string> scenes =
      options.has("scenes") ? parseSceneList(options.text("scenes", ""))
                            : std::vector<std::string>{"levee_drawdown", "block-1e6"};
  int rank = 0, size = 1;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  MPI_Comm_size(MPI_COMM_WORLD, &size);
  const double latency = allreduceLatency(2000);
  if (rank == 0) {
    std::ifstream in("/proc/loadavg");
    std::string load;
    std::getline(in, load);
    std::printf("%d ranks; Allreduce of 8 doubles: %.1f us; load average %s\n\n", size,
                1e6 * latency, load.c_str());
  }
  bool ok = true;
  std::vector<ProblemResult> results;
  for (const auto& name : scenes) {
    Problem problem;
    if (name.rfind(kLeveeDrawdown, 0) == 0) {
      const LeveeSceneName levee = parseLeveeScene(name);
      problem = leveeScene(name, levee.deck, levee.element_size);
    } else
      problem = name == "block-1e6" ? millionPointBlock() : benchmarkScene(name);
    if (options.has("steps")) problem.steps = static_cast<int>(options.number("steps", 10));
    results.push_back(runProblem(problem, settings));
    ok = results.back().finite && ok;
    // Reproducible sums do not depend on the number of ranks: different bits are a bug.
    if (settings.reproducible_sums && !results.back().same_bits) ok = false;
  }
  if (rank == 0 && results.size() > 1) printSummary(results, size);
  return ok ? 0 : 1;
}

}  // namespace
}  // namespace argine::benchmark

int main(int argc, char** argv) {
  return argine::verification::runVerification(argc, argv, argine::benchmark::run);
}
