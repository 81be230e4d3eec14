/// @file benchmark_main.cpp
/// argine_benchmark: material-point updates per second of the explicit two-phase step
/// (ExplicitTwoPhaseSolver) on the scenes of BenchmarkScenes.hpp, and where the time goes
/// (StepProfile). Prints, per scene: points, steps, wall time, updates per second by wall
/// and by process CPU time (on a loaded machine the CPU rate leaves out the time other jobs
/// held the core, not their use of the shared caches and memory), the median over the
/// repeats, and the profile split of the median repeat.
///
///   argine_benchmark [--scenes quad4-saturated,tri3-saturated,...] [--steps 100]
///                    [--repeat 3] [--warmup 5] [--sort-interval N] [--update-interval 1]
///                    [--shuffle] [--reproducible-sums] [--dump PREFIX]
///
/// --scenes schemes: the Mohr-Coulomb block on each shape family and velocity transfer
/// (BenchmarkScenes.hpp); with several scenes a closing table lists each one's rates and
/// fingerprint.
/// --sort-interval: steps between sorts of the points by element (0: never; default the
/// solver's recommended interval). --update-interval: recompute the critical time step every
/// N steps (the deck's Time Step/Update Interval; default 1 as in the deck). --shuffle:
/// permute the points randomly first (points mixed by large deformations).
/// --reproducible-sums: the binned node sums of `Parallel: {Reproducible Sums: true}`
/// (what they cost). The closing
/// fingerprint of each scene (a hash of all point fields in id order) tells whether two
/// builds give bit-for-bit the same results; --dump PREFIX writes the final point states
/// to PREFIX_<scene>.txt (in id order) to see by how much two builds differ.
/// Exit code 0 when every scene ran and gave finite, positive rates; speed is never judged.

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
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
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/timestep/Criteria.hpp"

namespace argine::benchmark {
namespace {

struct Settings {
  int steps = 100;
  int repeat = 3;
  int warmup = 5;
  int sort_interval = ExplicitTwoPhaseSolver::kRecommendedSortInterval;
  int update_interval = 1;
  bool shuffle = false;
  bool reproducible_sums = false;
};

/// One timed block of steps.
struct Sample {
  double wall = 0;  ///< s
  double cpu = 0;   ///< process CPU s
  StepProfile profile;
};

std::string loadAverage() {
  std::ifstream in("/proc/loadavg");
  std::string one, five, fifteen;
  if (!(in >> one >> five >> fifteen)) return "unknown";
  return one + " " + five + " " + fifteen;
}

/// Writes the state of every point, in id order, one line each: id, x, y, u_x, u_y, v_S, v_L,
/// p_L, S_L, n, V, M_L, sigma' (4), strain (4), with 17 digits (for comparing builds).
void dumpPoints(const MaterialPoints& points, const std::string& path) {
  auto host = [](const auto& view) {
    return Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
  };
  const auto id = host(points.id);
  const auto x = host(points.position), u = host(points.displacement);
  const auto vs = host(points.velocity_solid), vl = host(points.velocity_liquid);
  const auto pressure = host(points.pressure_liquid), saturation = host(points.saturation);
  const auto porosity = host(points.porosity), volume = host(points.volume);
  const auto liquid = host(points.mass_liquid);
  const auto stress = host(points.stress_effective), strain = host(points.strain);
  std::vector<int> index_of_id(points.count);
  for (int p = 0; p < points.count; ++p) index_of_id.at(id(p)) = p;
  std::FILE* out = std::fopen(path.c_str(), "w");
  if (!out) throw std::runtime_error("cannot write " + path);
  for (const int p : index_of_id) {
    std::fprintf(out, "%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g",
                 id(p), x(p, 0), x(p, 1), u(p, 0), u(p, 1), vs(p, 0), vs(p, 1), vl(p, 0), vl(p, 1),
                 pressure(p), saturation(p), porosity(p), volume(p));
    std::fprintf(out, " %.17g", liquid(p));
    for (int c = 0; c < kStressComponents; ++c) std::fprintf(out, " %.17g", stress(p, c));
    for (int c = 0; c < kStressComponents; ++c) std::fprintf(out, " %.17g", strain(p, c));
    std::fprintf(out, "\n");
  }
  std::fclose(out);
}

/// What a scene gave, for the closing table.
struct SceneResult {
  std::string name;
  double wall_rate = 0;  ///< point updates per wall second, median repeat
  double cpu_rate = 0;   ///< per process CPU second (per core: the step is serial)
  unsigned long long fingerprint = 0;
  bool finite = false;  ///< every rate finite and positive
};

/// Runs one scene.
SceneResult runScene(const std::string& name, const Settings& settings, const std::string& dump) {
  Scene scene = makeScene(name);
  if (settings.shuffle) shufflePoints(scene.points);
  scene.stage.time_step.update_interval = settings.update_interval;
  ExplicitTwoPhaseSolver solver(scene.mesh, scene.points, scene.materials);
  solver.setSortInterval(settings.sort_interval);
  solver.setReproducibleSums(settings.reproducible_sums);
  solver.beginStage(scene.stage);
  for (int k = 0; k < settings.warmup; ++k) solver.step(solver.chooseTimeStep().time_step);

  std::vector<Sample> samples;
  for (int r = 0; r < settings.repeat; ++r) {
    solver.resetProfile();
    Sample sample;
    const auto start = std::chrono::steady_clock::now();
    const std::clock_t cpu_start = std::clock();
    for (int k = 0; k < settings.steps; ++k) solver.step(solver.chooseTimeStep().time_step);
    sample.wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    sample.cpu = static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    sample.profile = solver.profile();
    samples.push_back(sample);
  }
  std::sort(samples.begin(), samples.end(),
            [](const Sample& a, const Sample& b) { return a.wall < b.wall; });
  const Sample& median = samples[samples.size() / 2];
  const double updates = static_cast<double>(scene.points.count) * settings.steps;

  std::ostringstream rates, cpu_rates;
  bool finite = true;
  for (const Sample& s : samples) {
    const double rate = updates / s.wall;
    finite = finite && std::isfinite(rate) && rate > 0 && std::isfinite(updates / s.cpu);
    rates << " " << rate;
    cpu_rates << " " << updates / s.cpu;
  }
  int elements_with_points = 0;
  for (const auto& block : scene.mesh.blocks)
    if (block.name == "soil") elements_with_points += static_cast<int>(block.elements.size());

  std::printf("scene %s: %d points, %d elements (%d with points), %d nodes (%d active)\n",
              name.c_str(), scene.points.count, scene.mesh.numElements(), elements_with_points,
              scene.mesh.numNodes(), solver.diagnostics().active_nodes);
  std::printf("  %d steps x %d repeats after %d warm-up steps, sort every %d, dt every %d, %s%s\n",
              settings.steps, settings.repeat, settings.warmup, settings.sort_interval,
              settings.update_interval, settings.shuffle ? "points shuffled" : "points seeded",
              settings.reproducible_sums ? ", reproducible sums" : "");
  std::printf("  dt = %.3g s (%s), load average %s\n", solver.diagnostics().time_step,
              criterionName(solver.diagnostics().time_step_choice.governing),
              loadAverage().c_str());
  std::printf("  median: wall %.3f s = %.3g point updates/s; CPU %.3f s = %.3g per core\n",
              median.wall, updates / median.wall, median.cpu, updates / median.cpu);
  std::printf("  all repeats, wall rate:%s\n", rates.str().c_str());
  std::printf("  all repeats, CPU rate: %s\n", cpu_rates.str().c_str());
  std::printf("  profile of the median repeat:\n%s", median.profile.describe("    ").c_str());
  // Equal fingerprints = bit-for-bit equal point states (same scene, steps and settings).
  const unsigned long long hash = fingerprint(scene.points);
  std::printf("  final state fingerprint %016llx\n\n", hash);
  if (!dump.empty()) dumpPoints(scene.points, dump + "_" + name + ".txt");
  return {name, updates / median.wall, updates / median.cpu, hash, finite};
}

void printSummary(const std::vector<SceneResult>& results) {
  std::printf("%-34s %14s %14s  %s\n", "scene", "updates/s", "per core (CPU)", "fingerprint");
  for (const SceneResult& r : results)
    std::printf("%-34s %14.3g %14.3g  %016llx\n", r.name.c_str(), r.wall_rate, r.cpu_rate,
                r.fingerprint);
}

int run(int argc, char** argv) {
  const verification::CommandLine options(
      argc, argv,
      {"scenes", "steps", "repeat", "warmup", "sort-interval", "update-interval", "shuffle",
       "reproducible-sums", "dump"});
  Settings settings;
  settings.steps = static_cast<int>(options.number("steps", settings.steps));
  settings.repeat = std::max(1, static_cast<int>(options.number("repeat", settings.repeat)));
  settings.warmup = static_cast<int>(options.number("warmup", settings.warmup));
  settings.sort_interval =
      static_cast<int>(options.number("sort-interval", settings.sort_interval));
  settings.update_interval =
      static_cast<int>(options.number("update-interval", settings.update_interval));
  settings.shuffle = options.has("shuffle");
  settings.reproducible_sums = options.has("reproducible-sums");
  const std::vector<std::string> scenes =
      options.has("scenes") ? parseSceneList(options.text("scenes", "")) : sceneNames();
  bool ok = true;
  const std::string dump = options.text("dump", "");
  std::vector<SceneResult> results;
  for (const std::string& scene : scenes) {
    results.push_back(runScene(scene, settings, dump));
    ok = results.back().finite && ok;
  }
  if (results.size() > 1) printSummary(results);
  return ok ? 0 : 1;
}

}  // namespace
}  // namespace argine::benchmark

int main(int argc, char** argv) {
  return argine::verification::runVerification(argc, argv, argine::benchmark::run);
}
