// V3 1D infiltration into a rigid column (VERIFICATION.md V3), implicit seepage path: the deck's
// column (20 rows, theta = 1, steps <= 2 s) against a refined implicit reference (4x finer mesh,
// 4x smaller steps, same theta), p_L(y) and S_L(y) at 100, 200, 400, 600 s within 2 % of their
// range; liquid mass balance error <= 1e-3. Then error vs wall time for a few meshes, steps
// and theta into infiltration_column_study.csv (plot_infiltration_column.py draws it).
//   infiltration_column_verification --output DIR [--deck DECK] [--no-study]
// --deck: another deck of the same column (e.g. infiltration_column_newton.yaml, the Newton
// iteration); --no-study: the verification only (no study CSV, no profile CSV).
#include <mpi.h>

#include <Kokkos_Core.hpp>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <string>
#include <vector>

#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/materials/RetentionCurve.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/PointInitialisation.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/seepage/ImplicitSeepageSolver.hpp"
#include "argine/simulation/Setup.hpp"

namespace argine {
namespace {

const std::vector<Real> kTimes{100, 200, 400, 600};

/// p_L along the left edge (x = 0) at each output time: (y, p) sorted by y.
struct Profile {
  std::vector<Real> y, p;
};

struct RunResult {
  std::vector<Profile> profiles;  // one per kTimes entry
  Real mass_balance_error = 0;    // |stored - inflow| / inflow
  Real wall_seconds = 0;
  Real cpu_seconds = 0;  // processor time: the wall time on an idle core
  long long steps = 0;
  long long iterations = 0;  // non-linear (Picard or Newton) iterations
  Real ponding_time = -1;    // first output check (every 10 s) with held top nodes
};

RunResult run(const Deck& base, Real element_size, Real theta, Real max_step) {
  Deck deck = base;
  deck.mesh.generator.element_size = element_size;
  deck.mesh.generator.upper_right[0] = element_size;  // one element (two triangles) wide
  StageSpec stage = deck.stages.at(0);
  stage.seepage.theta = theta;
  stage.seepage.max_step = max_step;
  stage.seepage.initial_step = std::min(stage.seepage.initial_step, max_step);
  const Mesh mesh = loadMesh(deck);
  MaterialPoints points = seedPoints(deck, mesh);
  initialisePointState(deck.materials, points);

  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  ImplicitSeepageSolver solver(mesh, points, deck.materials);
  solver.beginStage(stage);
  const Real initial_mass = solver.liquidMass();
  RunResult result;
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  for (const Real target : kTimes) {
    while (solver.time() < target - 1e-9) {
      solver.advanceTo(std::min(target, solver.time() + 10));
      if (result.ponding_time < 0 && !solver.heldNodes().empty())
        result.ponding_time = solver.time();
    }
    const std::vector<Real> p = solver.nodalPressure();
    Profile profile;
    std::vector<std::pair<Real, Real>> column;
    for (int n = 0; n < mesh.numNodes(); ++n)
      if (std::fabs(X(n, 0)) < 1e-12) column.push_back({X(n, 1), p[n]});
    std::sort(column.begin(), column.end());
    for (const auto& [y, value] : column) {
      profile.y.push_back(y);
      profile.p.push_back(value);
    }
    result.profiles.push_back(profile);
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.cpu_seconds = static_cast<Real>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const Real stored = solver.liquidMass() - initial_mass;
  result.mass_balance_error = std::fabs(stored - solver.totals().inflow) / solver.totals().inflow;
  result.steps = solver.totals().steps;
  result.iterations = solver.totals().picard_iterations;
  return result;
}

Real interpolate(const Profile& profile, Real y) {
  const auto it = std::lower_bound(profile.y.begin(), profile.y.end(), y);
  if (it == profile.y.begin()) return profile.p.front();
  if (it == profile.y.end()) return profile.p.back();
  const std::size_t j = it - profile.y.begin();
  const Real w = (y - profile.y[j - 1]) / (profile.y[j] - profile.y[j - 1]);
  return (1 - w) * profile.p[j - 1] + w * profile.p[j];
}

/// Largest error of p_L and S_L over the output times, each relative to the reference's range
/// at that time (the range of S_L, p_L along the column).
std::pair<Real, Real> profileErrors(const RunResult& run, const RunResult& reference,
                                    const RetentionSpec& retention) {
  Real error_p = 0, error_s = 0;
  for (std::size_t t = 0; t < kTimes.size(); ++t) {
    const Profile& ref = reference.profiles[t];
    const auto [p_min, p_max] = std::minmax_element(ref.p.begin(), ref.p.end());
    Real s_min = 1, s_max = 0;
    for (const Real p : ref.p) {
      const Real s = saturation(retention, suctionOfPressure(p));
      s_min = std::min(s_min, s);
      s_max = std::max(s_max, s);
    }
    const Real range_p = *p_max - *p_min, range_s = std::max<Real>(s_max - s_min, 1e-12);
    const Profile& mine = run.profiles[t];
    for (std::size_t i = 0; i < mine.y.size(); ++i) {
      const Real p_ref = interpolate(ref, mine.y[i]);
      error_p = std::max(error_p, std::fabs(mine.p[i] - p_ref) / range_p);
      // S_L of the reference's p_L interpolated at the node (S_L is what the SWRC gives there).
      error_s = std::max(error_s, std::fabs(saturation(retention, suctionOfPressure(mine.p[i])) -
                                            saturation(retention, suctionOfPressure(p_ref))) /
                                      range_s);
    }
  }
  return {error_p, error_s};
}

int verify(const std::string& output, const std::string& deck_path, bool study_too) {
  const Deck deck = readDeck(deck_path);
  const bool newton = deck.stages.at(0).seepage.iteration == SeepageIteration::Newton;
  const RetentionSpec retention = deck.materials.at(0).retention;
  const Real h = deck.mesh.generator.element_size;
  const Real dt = deck.stages.at(0).seepage.max_step;
  const Real theta = deck.stages.at(0).seepage.theta;

  const RunResult reference = run(deck, h / 4, theta, dt / 4);
  const RunResult base = run(deck, h, theta, dt);
  const auto [error_p, error_s] = profileErrors(base, reference, retention);
  std::printf(
      "V3 implicit (%s): h %.4g m, dt <= %.3g s, theta %.2g: %lld steps, %lld iterations, "
      "%.3f s wall; top ponds at %.0f s\n",
      newton ? "Newton" : "Picard", h, dt, theta, base.steps, base.iterations, base.wall_seconds,
      base.ponding_time);
  std::printf(
      "V3 implicit vs refined reference (h/4, dt/4; %lld steps, %lld iterations, %.3f s): max "
      "p_L error %.4f of range, max S_L error %.4f of range (bound 0.02)\n",
      reference.steps, reference.iterations, reference.wall_seconds, error_p, error_s);
  std::printf("V3 implicit: liquid mass balance error %.3e (reference %.3e; bound 1e-3)\n",
              base.mass_balance_error, reference.mass_balance_error);

  const bool ok = error_p <= 0.02 && error_s <= 0.02 && base.mass_balance_error <= 1e-3 &&
                  base.ponding_time > 0;
  if (!study_too) {
    std::printf("V3 implicit: %s\n", ok ? "PASSED" : "FAILED");
    return ok ? 0 : 1;
  }
  // Profiles for the plot.
  {
    std::ofstream out(output + "/infiltration_column_profiles.csv");
    out << "run,time,y,p_L,S_L\n";
    for (const auto* r : {&base, &reference})
      for (std::size_t t = 0; t < kTimes.size(); ++t)
        for (std::size_t i = 0; i < r->profiles[t].y.size(); ++i)
          out << (r == &base ? "implicit" : "reference") << ',' << kTimes[t] << ','
              << r->profiles[t].y[i] << ',' << r->profiles[t].p[i] << ','
              << saturation(retention, suctionOfPressure(r->profiles[t].p[i])) << '\n';
  }
  // Error vs wall time.
  std::ofstream study(output + "/infiltration_column_study.csv");
  study << "element_size,max_step,theta,steps,wall_seconds,cpu_seconds,error_p,error_S,"
           "mass_balance_error\n";
  for (const Real study_theta : {1.0, 0.5})
    for (const Real size : {0.1, 0.05, 0.025})
      for (const Real step : {8.0, 2.0, 0.5}) {
        const RunResult r = run(deck, size, study_theta, step);
        const auto [ep, es] = profileErrors(r, reference, retention);
        study << size << ',' << step << ',' << study_theta << ',' << r.steps << ','
              << r.wall_seconds << ',' << r.cpu_seconds << ',' << ep << ',' << es << ','
              << r.mass_balance_error << '\n';
        std::printf(
            "study: h %.3g dt <= %.3g theta %.2g: %5lld steps %.3f s: p_L %.4f S_L %.4f "
            "mass %.1e\n",
            size, step, study_theta, r.steps, r.wall_seconds, ep, es, r.mass_balance_error);
      }
  std::printf("V3 implicit: %s\n", ok ? "PASSED" : "FAILED");
  return ok ? 0 : 1;
}

}  // namespace
}  // namespace argine

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  int code = 1;
  {
    Kokkos::ScopeGuard kokkos(argc, argv);
    std::string output = ".", deck = ARGINE_V3_DECK;
    bool study = true;
    for (int i = 1; i < argc; ++i) {
      const std::string arg = argv[i];
      if (arg == "--output" && i + 1 < argc) output = argv[i + 1];
      if (arg == "--deck" && i + 1 < argc) deck = argv[i + 1];
      if (arg == "--no-study") study = false;
    }
    try {
      code = argine::verify(output, deck, study);
    } catch (const std::exception& error) {
      std::fprintf(stderr, "infiltration_column_verification: %s\n", error.what());
    }
  }
  MPI_Finalize();
  return code;
}
