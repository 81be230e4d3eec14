// V4 2D transient seepage through a levee on the IMPLICIT seepage path (VERIFICATION.md V4),
// compared with a refined implicit reference and with the explicit path's section CSVs.
//
// Runs levee_seepage_implicit.yaml (backward Euler, adaptive step, Tri3 0.05 m, 3 points per
// element) from the hydrostatic profile p_L = rho_L g (0.2 - y), at several settings, and a
// reference (Tri3 0.025 m, steps <= 0.5 s, |dS_L| <= 0.02 per step). Profiles on the sections S1 (x
// = 1.5 m) and S2 (x = 3.0 m) at 72, 160 and 300 s are sampled at y = 0.0125 + 0.025 k (k = 0..29,
// up to the slope at y = 0.75 m):
//   - implicit runs: the finite-element field (nodal p_L, Tri3 interpolation) at (x_s, y);
//   - explicit runs (`--explicit FILE`, repeatable as --explicit2 FILE: <tag>_sections.csv of
//     levee_seepage_verification, the points within 0.03 m of the section): a least-squares
//     plane p = a + b dx + c dy through the points within 0.05 m in y, evaluated at (x_s, y)
//     (the explicit path has one pressure per point, with Tri3 checkerboard modes; the plane
//     reads its local mean). The same fit is applied to the implicit run's own points and
//     printed, to show what the fit alone changes.
// Error: max |p - p_ref| over all samples / (max - min of p_ref over all samples); the same
// for S_L (SectionProfiles.hpp). Writes <tag>_sections.csv (implicit points, same format as
// the explicit driver), <tag>_profiles.csv (sampled profiles of every run) and <tag>_cost.csv
// (error against wall and CPU time of every run).
// The accuracy-against-cost study (scripts/accuracy_cost.sh): --study adds implicit runs on
// h 0.1 and 0.025 m, coarse steps and Crank-Nicolson; --reference-profiles FILE takes the
// reference's samples from an earlier <tag>_profiles.csv instead of rerunning it;
// --explicit-runs P1,P2,... reads explicit runs of levee_seepage_verification (their
// P_sections.csv and P_cost.csv).
// Asserts (VERIFICATION.md V4: agreement within 3 % of the p_L range): the default implicit
// run vs the reference, and the liquid mass balance (|storage - inflow| <= 1e-10 of the
// largest of |storage|, |inflow|, or 1e-10 kg/m when both vanish). With --assert-explicit also
// the --explicit run (the V4 deck, with its liquid head stabilisation) within 3 %; --explicit2
// (the unstabilised deck) and the study's runs are printed only.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <ctime>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

#include "CommandLine.hpp"
#include "SectionProfiles.hpp"
#include "VerificationMain.hpp"
#include "argine/init/Initialisation.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/PointInitialisation.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/seepage/ImplicitSeepageSolver.hpp"
#include "argine/seepage/SeepagePointTerms.hpp"
#include "argine/simulation/Setup.hpp"

namespace av = argine::verification;
using argine::Real;
using namespace argine::verification::v4;

namespace {

constexpr Real kWaterTable = 0.2;

struct RunResult {
  std::string name;
  Samples fe;          // finite-element field at the samples
  Samples points_fit;  // the plane fit through the run's own points
  std::vector<PointRow> rows;
  Real wall_seconds = 0;
  Real cpu_seconds = 0;  // processor time: the wall time on an idle core
  long long steps = 0;
  Real balance = 0;  // |storage - inflow| / max(|storage|, |inflow|)
};

/// Tri3 interpolation of nodal values at (x, y): NaN outside the mesh or at inactive nodes.
Real feValue(const argine::Mesh& mesh, const std::vector<Real>& nodal, Real x, Real y) {
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto C = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  for (int e = 0; e < mesh.numElements(); ++e) {
    const int a = C(e, 0), b = C(e, 1), c = C(e, 2);
    const Real x1 = X(a, 0), y1 = X(a, 1), x2 = X(b, 0), y2 = X(b, 1), x3 = X(c, 0), y3 = X(c, 1);
    const Real det = (y2 - y3) * (x1 - x3) + (x3 - x2) * (y1 - y3);
    const Real l1 = ((y2 - y3) * (x - x3) + (x3 - x2) * (y - y3)) / det;
    const Real l2 = ((y3 - y1) * (x - x3) + (x1 - x3) * (y - y3)) / det;
    const Real l3 = 1 - l1 - l2;
    if (l1 < -1e-12 || l2 < -1e-12 || l3 < -1e-12) continue;
    const Real v = l1 * nodal[a] + l2 * nodal[b] + l3 * nodal[c];
    if (std::isnan(v)) continue;
    return v;
  }
  return std::nan("");
}

/// One implicit run's settings (the deck's own for what is not named here).
struct ImplicitSettings {
  std::string name;
  Real element_size, max_step, max_saturation_change, theta = 1;
};

RunResult runImplicit(const argine::Deck& base, const ImplicitSettings& settings) {
  const auto& [name, element_size, max_step, max_saturation_change, theta] = settings;
  argine::Deck deck = base;
  deck.mesh.generator.element_size = element_size;
  argine::StageSpec stage = deck.stages.at(0);
  stage.seepage.theta = theta;
  stage.seepage.max_step = max_step;
  stage.seepage.initial_step = std::min(stage.seepage.initial_step, max_step);
  stage.seepage.max_saturation_change = max_saturation_change;
  const argine::Mesh mesh = argine::loadMesh(deck);
  argine::MaterialPoints points = argine::seedPoints(deck, mesh);
  (void)argine::initialisePoints(deck, mesh, points);  // the deck's water table at 0.2 m

  const auto start = std::chrono::steady_clock::now();
  const std::clock_t cpu_start = std::clock();
  argine::ImplicitSeepageSolver solver(mesh, points, deck.materials);
  solver.beginStage(stage);
  solver.handOver();  // the points' rho_L, S_L, M_L consistent with the nodal start
  const Real initial_mass = solver.liquidMass();
  const argine::MaterialTable table(deck.materials);
  const argine::PointMaterial& material = table.host(0);
  RunResult result;
  result.name = name;
  const std::vector<Real> heights = sampleHeights();
  for (const Real t : kTimes) {
    solver.advanceTo(t);
    solver.handOver();
    const std::vector<Real> p = solver.nodalPressure();
    for (const auto& [section, xs] : kSections)
      for (const Real y : heights) {
        const Real value = feValue(mesh, p, xs, y);
        result.fe.p.push_back(value);
        result.fe.s.push_back(std::isnan(value)
                                  ? value
                                  : argine::saturationAndConductivity(material, value).saturation);
      }
    const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.position);
    const auto P = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.pressure_liquid);
    const auto S = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.saturation);
    for (int k = 0; k < points.count; ++k)
      for (const auto& [section, xs] : kSections)
        if (std::fabs(X(k, 0) - xs) <= kStrip)
          result.rows.push_back({t, X(k, 0), X(k, 1), P(k), S(k), section});
  }
  result.wall_seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  result.cpu_seconds = static_cast<Real>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
  const Real stored = solver.liquidMass() - initial_mass, inflow = solver.totals().inflow;
  const Real scale = std::max({std::fabs(stored), std::fabs(inflow), Real(1e-10)});
  result.balance = std::fabs(stored - inflow) / scale;
  result.steps = solver.totals().steps;
  result.points_fit = fitRows(result.rows);
  std::printf(
      "[ V4i ] %-22s h = %.4f m, max step %.3g s, dS %.3g, theta %.2g: %lld steps, %.2f s "
      "wall, %.2f s CPU, %d points, storage %.6g kg/m, inflow %.6g kg/m, balance %.2e\n",
      name.c_str(), element_size, max_step, max_saturation_change, theta, result.steps,
      result.wall_seconds, result.cpu_seconds, points.count, stored, inflow, result.balance);
  return result;
}

/// One explicit run of the study: <prefix>_sections.csv and <prefix>_cost.csv written by
/// levee_seepage_verification (element size, mass scaling, points, steps, wall and CPU time).
struct ExplicitRun {
  std::string name;
  std::vector<PointRow> rows;
  std::map<std::string, std::string> cost;  // header -> value of <prefix>_cost.csv
};

ExplicitRun readExplicitRun(const std::string& prefix) {
  ExplicitRun run;
  run.name = prefix.substr(prefix.find_last_of('/') + 1);
  run.rows = readSectionCsv(prefix + "_sections.csv");
  std::ifstream in(prefix + "_cost.csv");
  std::string header, values;
  std::getline(in, header);
  std::getline(in, values);
  std::stringstream h(header), v(values);
  std::string key, value;
  while (std::getline(h, key, ',') && std::getline(v, value, ',')) run.cost[key] = value;
  return run;
}

int run(int argc, char** argv) {
  const av::CommandLine options(
      argc, argv,
      {"deck", "output", "tag", "explicit", "explicit2", "assert-explicit", "quick", "study",
       "reference-profiles", "explicit-runs"});
  const argine::Deck deck =
      argine::readDeck(options.text("deck", ARGINE_LEVEE_SEEPAGE_IMPLICIT_DECK));
  const std::string output = options.text("output", ".");
  const std::string tag = options.text("tag", "levee_seepage_implicit");
  const bool quick = options.has("quick");

  std::vector<ImplicitSettings> settings{{"implicit", 0.05, 1.0, 0.05}};
  if (!quick) settings.push_back({"implicit_coarse_step", 0.05, 5.0, 0.2});
  if (options.has("study")) {  // the implicit side of the accuracy-against-cost chart
    settings.push_back({"implicit_h0.1", 0.1, 1.0, 0.05});
    settings.push_back({"implicit_h0.1_coarse_step", 0.1, 5.0, 0.2});
    settings.push_back({"implicit_crank_nicolson", 0.05, 1.0, 0.05, 0.5});
    settings.push_back({"implicit_h0.025_coarse_step", 0.025, 5.0, 0.2});
  }
  std::vector<RunResult> runs;
  for (const ImplicitSettings& s : settings) runs.push_back(runImplicit(deck, s));
  // The reference: the refined implicit run, or its samples from an earlier run's profiles.
  RunResult reference;
  if (options.has("reference-profiles")) {
    const std::string path = options.text("reference-profiles", "");
    reference.name = "reference";
    reference.fe = readProfiles(path, "reference");
    if (reference.fe.p.empty()) {
      std::printf("[ V4i ] no run 'reference' in %s\n", path.c_str());
      return av::kExitCannotRun;
    }
    std::printf("[ V4i ] reference samples read from %s\n", path.c_str());
  } else {
    reference = quick ? runImplicit(deck, {"reference", 0.05, 0.25, 0.01})
                      : runImplicit(deck, {"reference", 0.025, 0.5, 0.02});
  }

  std::ofstream sections(output + "/" + tag + "_sections.csv");
  sections << "time,section,x,y,pressure,saturation\n";
  for (const PointRow& r : runs.front().rows)
    sections << r.t << "," << r.section << "," << r.x << "," << r.y << "," << r.p << "," << r.s
             << "\n";

  // error against cost of every run: path, discretisation, cost, error
  std::ofstream cost(output + "/" + tag + "_cost.csv");
  cost << "run,path,element_size,max_step,theta,mass_scaling,wall_seconds,cpu_seconds,steps,"
          "p_error,s_error\n";
  std::map<std::string, Samples> profiles{{"reference", reference.fe}};
  bool ok = true;
  Errors main_errors;
  for (std::size_t k = 0; k < runs.size(); ++k) {
    const RunResult& r = runs[k];
    const Errors e = compare(r.fe, reference.fe);
    const Errors f = compare(r.points_fit, reference.fe);
    std::printf(
        "[ V4i ] %-22s vs reference: max |dp_L| %.3f %% of range, |dS_L| %.3f %% (%d "
        "samples); plane fit through its points: %.3f %%, %.3f %%\n",
        r.name.c_str(), 100 * e.p, 100 * e.s, e.compared, 100 * f.p, 100 * f.s);
    cost << r.name << ",implicit," << settings[k].element_size << "," << settings[k].max_step << ","
         << settings[k].theta << ",," << r.wall_seconds << "," << r.cpu_seconds << "," << r.steps
         << "," << e.p << "," << e.s << "\n";
    profiles[r.name] = r.fe;
    if (r.name == "implicit") main_errors = e;
    if (!(r.balance <= 1e-10)) ok = false;
  }
  if (!options.has("reference-profiles") && !(reference.balance <= 1e-10)) ok = false;
  if (!(main_errors.p <= 0.03) || main_errors.compared < 100) ok = false;

  // The explicit runs: the sections of the CTest runs (--explicit, --explicit2) and those
  // of the study (--explicit-runs PREFIX,PREFIX,...), each through the plane fit.
  std::vector<ExplicitRun> explicit_runs;
  for (const char* key : {"explicit", "explicit2"}) {
    if (!options.has(key)) continue;
    ExplicitRun run;
    run.name = key;
    const std::string path = options.text(key, "");
    run.rows = readSectionCsv(path);
    if (run.rows.empty()) {
      std::printf("[ V4i ] %s: no rows in %s (run levee_seepage_verification first)\n", key,
                  path.c_str());
      ok = false;
      continue;
    }
    explicit_runs.push_back(run);
  }
  for (const std::string& prefix : options.texts("explicit-runs")) {
    ExplicitRun run = readExplicitRun(prefix);
    if (run.rows.empty() || run.cost.empty()) {
      std::printf("[ V4i ] %s: no %s_sections.csv or _cost.csv\n", run.name.c_str(),
                  prefix.c_str());
      ok = false;
      continue;
    }
    explicit_runs.push_back(run);
  }
  for (const ExplicitRun& run : explicit_runs) {
    // A window of one element at least (the study's coarse explicit meshes).
    const auto size = run.cost.find("element_size");
    const Real element = size == run.cost.end() ? 0 : std::stod(size->second);
    const Samples fitted = fitRows(run.rows, std::max(kFitHalf, element));
    const Errors e = compare(fitted, reference.fe);
    const Errors i = compare(fitted, runs.front().fe);
    std::printf(
        "[ V4i ] %s: vs reference max |dp_L| %.2f %% of range, |dS_L| %.2f %%; vs "
        "implicit %.2f %%, %.2f %% (%d samples)\n",
        run.name.c_str(), 100 * e.p, 100 * e.s, 100 * i.p, 100 * i.s, e.compared);
    auto field = [&](const char* name) {
      const auto found = run.cost.find(name);
      return found == run.cost.end() ? std::string() : found->second;
    };
    cost << run.name << ",explicit," << field("element_size") << ",,," << field("mass_scaling")
         << "," << field("wall_seconds") << "," << field("cpu_seconds") << "," << field("steps")
         << "," << e.p << "," << e.s << "\n";
    profiles[run.name] = fitted;
    if (options.has("assert-explicit") && run.name == "explicit" && !(e.p <= 0.03)) ok = false;
  }

  std::ofstream out(output + "/" + tag + "_profiles.csv");
  out << "run,time,section,y,pressure,saturation\n";
  const std::vector<Real> heights = sampleHeights();
  for (const auto& [name, samples] : profiles) {
    std::size_t k = 0;
    for (const Real t : kTimes)
      for (const auto& section : kSections)
        for (const Real y : heights) {
          out << name << "," << t << "," << section.first << "," << y << "," << samples.p[k] << ","
              << samples.s[k] << "\n";
          ++k;
        }
  }
  std::printf(
      "[ V4i ] implicit vs reference %.3f %% of the p_L range (bound 3 %%); mass "
      "balance bound 1e-10\n[ V4i ] %s\n",
      100 * main_errors.p, ok ? "PASS" : "FAIL: a bound is exceeded");
  return ok ? 0 : av::kExitBoundExceeded;
}

}  // namespace

int main(int argc, char** argv) {
  return av::runVerification(argc, argv, run);
}
