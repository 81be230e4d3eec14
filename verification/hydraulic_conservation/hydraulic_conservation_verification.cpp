// V6 liquid mass conservation of the hydraulic boundary conditions (VERIFICATION.md V6,
// doc/theory.md "Hydraulic conditions on the moving boundary"), and the ponding switch of
// the infiltration condition (rain above k_sat on a 1D column).
//
// Runs one deck (one stage, fixed skeleton) to its end, sampling at its output interval,
// and checks at every sample:
//   conservation: |storage change - sum of the conditions' inflows| <= bound x max |storage|
//                 (bound 1e-3 of VERIFICATION.md V6), the storage change being the change
//                 of the points' liquid mass / rho_L and the inflows what the solver reports
//                 per condition and step (summed);
// and, by --mode:
//   rain     the infiltration's inflow = integral of q(t) x top width within 0.5 %;
//   runoff   rain above k_sat without ponding: the surface reaches zero pressure and the
//            rest runs off: inflow < 0.95 x the rain, and the top points' p_L within one
//            element's hydrostatic head of zero (|p_L| <= rho g h_e; it starts at -5 kPa);
//   ponding  rain above k_sat with ponding: inflow = the rain within 0.5 %, top p_L > 0.
// Writes <output>/<tag>_balance.csv (time, storage, inflows, expected rain).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>

#include "CommandLine.hpp"
#include "HydraulicRun.hpp"
#include "VerificationMain.hpp"
#include "argine/boundary/HydraulicConditions.hpp"
#include "argine/input/DeckReader.hpp"

namespace av = argine::verification;
using argine::Real;

namespace {

constexpr const char* kUsage =
    "hydraulic_conservation_verification --deck FILE [--mode conservation|rain|runoff|ponding]\n"
    "  [--bound 1e-3] [--output DIR] [--tag NAME]\n";

/// Integral from 0 to t of a piecewise-linear series clamped at its ends (exact).
Real integral(const argine::TimeSeries& series, Real t) {
  std::vector<Real> times{0.0, t};
  for (const Real s : series.times())
    if (s > 0 && s < t) times.push_back(s);
  std::sort(times.begin(), times.end());
  Real sum = 0;
  for (std::size_t k = 1; k < times.size(); ++k)
    sum += 0.5 * (times[k] - times[k - 1]) * (series.at(times[k]) + series.at(times[k - 1]));
  return sum;
}

/// Largest p_L of the points within half an element of the top of the column.
Real topPressure(const av::HydraulicRun& run, Real top, Real element_size) {
  const auto& points = run.points();
  const auto y = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.position);
  const auto p = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.pressure_liquid);
  Real largest = -1e300;
  for (int k = 0; k < points.count; ++k)
    if (y(k, 1) > top - 0.5 * element_size) largest = std::max(largest, p(k));
  return largest;
}

int run(int argc, char** argv) {
  const av::CommandLine options(argc, argv, {"deck", "mode", "bound", "output", "tag"});
  if (!options.has("deck")) {
    std::cerr << kUsage;
    return av::kExitCannotRun;
  }
  const argine::Deck deck = argine::readDeck(options.text("deck", ""));
  const std::string mode = options.text("mode", "conservation");
  const Real bound = options.number("bound", 1e-3);
  const std::string tag = options.text("tag", deck.output.name);
  const std::string output = options.text("output", ".");
  const argine::StageSpec& stage = deck.stages.front();
  const auto& box = deck.mesh.generator;
  const Real width = box.upper_right[0] - box.lower_left[0];
  const Real top = box.upper_right[1];

  // the rain of an infiltration condition, for the rain / runoff / ponding checks
  argine::TimeSeries rain_series;
  std::string rain_name;
  for (const auto& boundary : stage.boundaries)
    if (boundary.kind == argine::BoundaryKind::Infiltration) {
      rain_series = argine::makeTimeSeries(boundary.hydraulic.series, 0.0);
      rain_name = boundary.name;
    }

  av::HydraulicRun run(deck);
  std::ofstream csv(output + "/" + tag + "_balance.csv");
  csv << "time,storage_change,sum_of_inflows";
  for (const auto& [name, value] : run.inflows()) csv << "," << name;
  csv << ",expected_rain,top_pressure\n";
  const Real interval = stage.output_interval > 0 ? stage.output_interval : stage.duration;
  Real worst = 0, largest_storage = 0;
  bool ok = true;
  for (Real t = interval; t <= stage.duration * (1 + 1e-12); t += interval) {
    run.advanceTo(std::min(t, stage.duration));
    const Real storage = run.storageChange(), inflow = run.totalInflow();
    largest_storage = std::max(largest_storage, std::fabs(storage));
    worst = std::max(worst, std::fabs(storage - inflow));
    const Real rain = rain_name.empty() ? 0 : integral(rain_series, run.time()) * width;
    const Real top_p = topPressure(run, top, box.element_size);
    csv << run.time() << "," << storage << "," << inflow;
    for (const auto& [name, value] : run.inflows()) csv << "," << value;
    csv << "," << rain << "," << top_p << "\n";
  }
  const Real relative = largest_storage > 0 ? worst / largest_storage : worst;
  std::printf(
      "[ V6 %s ] %ld steps in %.1f s wall; storage change %.6g m3/m, inflows %.6g m3/m;"
      " largest |storage - inflows| / max |storage| = %.3g (bound %.0e)\n",
      tag.c_str(), run.steps(), run.wallSeconds(), run.storageChange(), run.totalInflow(), relative,
      bound);
  if (!(relative <= bound)) ok = false;

  if (mode != "conservation") {
    const Real rain = integral(rain_series, run.time()) * width;
    const Real inflow = run.inflow(rain_name);
    const Real rho_g_h =
        deck.materials.front().liquid.density * argine::kStandardGravity * box.element_size;
    const Real top_p = topPressure(run, top, box.element_size);
    std::printf(
        "[ V6 %s ] rain %.6g m3/m, infiltrated %.6g m3/m (%.4f of the rain); top p_L "
        "%.4g Pa (rho g h_e = %.4g Pa)\n",
        tag.c_str(), rain, inflow, inflow / rain, top_p, rho_g_h);
    if (mode == "rain" && !(std::fabs(inflow - rain) <= 5e-3 * std::fabs(rain))) ok = false;
    if (mode == "runoff" && !(inflow < 0.95 * rain && std::fabs(top_p) <= rho_g_h)) ok = false;
    if (mode == "ponding" && !(std::fabs(inflow - rain) <= 5e-3 * rain && top_p > 0)) ok = false;
  }
  std::printf("[ V6 %s ] %s\n", tag.c_str(), ok ? "PASS" : "FAIL: a bound is exceeded");
  return ok ? 0 : av::kExitBoundExceeded;
}

}  // namespace

int main(int argc, char** argv) {
  return av::runVerification(argc, argv, run);
}
