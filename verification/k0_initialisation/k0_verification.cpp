// V6 second bullet (VERIFICATION.md): K0 initialisation of a layered, partly saturated
// column. sigma'_yy and p_L of every material point after the K0 procedure are compared with
// an independent profile: the layers' unit weights integrated from the ground surface down
// by a fine midpoint rule (here, not the code's Gauss pieces), with this file's own van
// Genuchten formula. Bound: 1 % of the largest |reference| (max norm) for both. Then the
// deck's quasi-static relaxation stage runs and the same comparison is reported (bound 2 %):
// the K0 state must be (nearly) in equilibrium.
//
// --hand-over --phreatic-after Y (deck k0_column_hand_over.yaml, issue P5): the deck ends
// with an implicit seepage stage that raises the water table to Y and a quasi-static stage
// with `Liquid Pressure: held`. The run without that last stage (the plain hand-over) and
// the whole run are compared with the profile for a table at Y (no cap): after the held
// stage sigma'_yy and p_L must be within the relaxed bound, and p_L of every point must be
// what the implicit stage handed over, exactly.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

#include "CommandLine.hpp"
#include "VerificationMain.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/simulation/Simulation.hpp"

namespace av = argine::verification;
using argine::Deck;
using argine::MaterialSpec;

namespace {

constexpr double kGravity = 9.81;  // the deck's stage gravity (checked below)

/// One horizontal layer of the column, from the deck's polygon regions.
struct Layer {
  double bottom = 0, top = 0;
  const MaterialSpec* material = nullptr;
};

/// S_L(s) of van Genuchten, written out here: S_min + (S_max - S_min) [1 + (s/p_ref)^(1/(1-l))]^-l.
double saturationOf(const MaterialSpec& m, double pressure) {
  if (m.phase == argine::PhaseModel::Dry) return 0;
  if (m.phase == argine::PhaseModel::Saturated || pressure >= 0) return 1;
  const auto& r = m.retention;
  const double s = -pressure;
  const double se = std::pow(1 + std::pow(s / r.reference_pressure, 1 / (1 - r.lambda)), -r.lambda);
  return r.saturation_min + (r.saturation_max - r.saturation_min) * se;
}

struct Reference {
  std::vector<Layer> layers;
  double ground = 0, phreatic = 0, cap = 0, rho_l = 1000;
  std::vector<double> y, sigma;  ///< fine grid from the ground down, total vertical stress

  const Layer& layerAt(double y_) const {
    for (const auto& l : layers)
      if (y_ >= l.bottom && y_ <= l.top) return l;
    throw std::runtime_error("no layer at y = " + std::to_string(y_));
  }
  double pressure(double y_) const { return std::max(rho_l * kGravity * (phreatic - y_), -cap); }
  double gamma(double y_) const {
    const MaterialSpec& m = *layerAt(y_).material;
    const double s = saturationOf(m, pressure(y_));
    return ((1 - m.porosity) * m.solid_density + m.porosity * s * rho_l) * kGravity;
  }
  void integrate(double bottom, double step) {
    // Midpoint rule, cell by cell from the ground down: sigma(y_k) = -sum gamma(mid) h.
    double total = 0, y_ = ground;
    y.push_back(y_);
    sigma.push_back(0);
    while (y_ > bottom + 1e-12) {
      const double h = std::min(step, y_ - bottom);
      total += gamma(y_ - 0.5 * h) * h;
      y_ -= h;
      y.push_back(y_);
      sigma.push_back(-total);
    }
  }
  double totalStress(double y_) const {  // linear interpolation on the fine grid
    const auto it = std::lower_bound(y.rbegin(), y.rend(), y_);
    const std::size_t k = y.size() - 1 - std::min<std::size_t>(it - y.rbegin(), y.size() - 1);
    if (k == 0) return sigma[0];
    const double t = (y_ - y[k]) / (y[k - 1] - y[k]);
    return sigma[k] + t * (sigma[k - 1] - sigma[k]);
  }
  double effectiveStress(double y_, const MaterialSpec& m) const {
    const double p = m.phase == argine::PhaseModel::Dry ? 0 : pressure(y_);
    return totalStress(y_) + saturationOf(m, p) * p;
  }
};

struct Errors {
  double stress = 0, pressure = 0;  ///< max |error| / max |reference|
};

Errors compare(const Reference& ref, const Deck& deck, const argine::MaterialPoints& points,
               const std::string& csv) {
  auto pos = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.position);
  auto mat = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.material);
  auto pl = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.pressure_liquid);
  auto sl = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.saturation);
  auto st = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.stress_effective);
  std::ofstream out(csv);
  out << "y,material,stress_yy,stress_yy_reference,liquid_pressure,liquid_pressure_reference,"
         "saturation\n";
  double max_s = 0, max_p = 0, err_s = 0, err_p = 0;
  for (int p = 0; p < points.count; ++p) {
    const double y = pos(p, 1);
    const MaterialSpec& m = deck.materials[mat(p)];
    const double s_ref = ref.effectiveStress(y, m);
    const double p_ref = ref.pressure(y);
    max_s = std::max(max_s, std::abs(s_ref));
    max_p = std::max(max_p, std::abs(p_ref));
    err_s = std::max(err_s, std::abs(st(p, argine::YY) - s_ref));
    err_p = std::max(err_p, std::abs(pl(p) - p_ref));
    out << y << "," << mat(p) << "," << st(p, argine::YY) << "," << s_ref << "," << pl(p) << ","
        << p_ref << "," << sl(p) << "\n";
  }
  return {err_s / max_s, err_p / max_p};
}

/// p_L of every point by its permanent id.
std::vector<double> pressuresById(const argine::MaterialPoints& points) {
  auto id = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.id);
  auto pl = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.pressure_liquid);
  std::vector<double> by_id(points.count, 0.0);
  for (int p = 0; p < points.count; ++p) by_id.at(id(p)) = pl(p);
  return by_id;
}

/// The hand-over check (see the file comment): the reference for the new table, the run
/// without its last (held) stage and the whole run.
int verifyHandOver(const Deck& deck, Reference ref, double phreatic_after,
                   const std::string& output, double relaxed_bound) {
  const argine::StageSpec& last = deck.stages.back();
  if (deck.stages.size() < 2 || !last.hold_liquid_pressure)
    throw argine::InputError(deck.path,
                             "--hand-over expects a last stage with Liquid Pressure: held");
  ref.phreatic = phreatic_after;
  ref.cap = 1e300;
  ref.y.clear();
  ref.sigma.clear();
  double bottom = 1e300;
  for (const auto& l : ref.layers) bottom = std::min(bottom, l.bottom);
  ref.integrate(bottom, 1e-4);

  argine::RunOptions run;
  run.quiet = true;
  Deck handed = deck;  // up to the implicit stage: the plain hand-over
  handed.stages.pop_back();
  run.output_directory = output + "/hand_over_plain";
  argine::Simulation plain(handed, run);
  plain.run();
  const Errors before = compare(ref, deck, plain.points(), output + "/k0_points_handed.csv");
  run.output_directory = output + "/hand_over_held";
  argine::Simulation held(deck, run);
  held.run();
  const Errors after = compare(ref, deck, held.points(), output + "/k0_points_held.csv");
  for (const auto& line : held.stageLog()) std::printf("  log: %s\n", line.c_str());
  const std::vector<double> p_before = pressuresById(plain.points());
  const std::vector<double> p_after = pressuresById(held.points());
  double changed = 0;
  for (std::size_t k = 0; k < p_before.size(); ++k)
    changed = std::max(changed, std::abs(p_after[k] - p_before[k]));

  std::printf("Hand-over (table at %.3g m, %d points), max error / max |reference|:\n",
              phreatic_after, held.points().count);
  std::printf("  implicit stage handed over:   sigma'_yy %.3e   p_L %.3e\n", before.stress,
              before.pressure);
  std::printf("  after the held-pressure stage: sigma'_yy %.3e   p_L %.3e   (bound %.3g)\n",
              after.stress, after.pressure, relaxed_bound);
  std::printf("  p_L changed by the held stage: max %.3e Pa (must be 0)\n", changed);
  std::ofstream errors(output + "/k0_hand_over_errors.csv");
  errors << "state,stress_error,pressure_error,bound\n"
         << "handed," << before.stress << "," << before.pressure << ",\n"
         << "held," << after.stress << "," << after.pressure << "," << relaxed_bound << "\n";
  const bool ok = after.stress <= relaxed_bound && after.pressure <= relaxed_bound &&
                  changed == 0 && p_before.size() == p_after.size();
  std::printf("Hand-over with the skeleton in equilibrium: %s\n",
              ok ? "PASSED" : "FAILED (bound exceeded)");
  return ok ? 0 : av::kExitBoundExceeded;
}

}  // namespace

int main(int argc, char** argv) {
  return av::runVerification(argc, argv, [](int argc_, char** argv_) {
    const av::CommandLine options(
        argc_, argv_, {"deck", "output", "bound", "relaxed-bound", "hand-over", "phreatic-after"});
    const std::string deck_path = options.text("deck", ARGINE_K0_DECK);
    const std::string output = options.text("output", ".");
    const double bound = options.number("bound", 0.01);
    const double relaxed_bound = options.number("relaxed-bound", 0.02);
    const Deck deck = argine::readDeck(deck_path);
    if (deck.initialisation.method != argine::InitialisationSpec::Method::K0Procedure ||
        deck.initialisation.phreatic_surface.empty() || deck.stages.empty() ||
        std::abs(deck.stages.front().gravity - kGravity) > 1e-12)
      throw argine::InputError(deck.path,
                               "V6 expects a K0 procedure with a phreatic surface "
                               "and a first stage with g = 9.81 m/s2");

    Reference ref;
    ref.ground = deck.initialisation.ground_surface.front()[1];
    ref.phreatic = deck.initialisation.phreatic_surface.front()[1];
    ref.cap = deck.initialisation.max_suction >= 0 ? deck.initialisation.max_suction : 1e300;
    for (const auto& region : deck.mesh.generator.regions) {
      Layer layer;
      layer.bottom = 1e300;
      layer.top = -1e300;
      for (const auto& v : region.vertices) {
        layer.bottom = std::min(layer.bottom, v[1]);
        layer.top = std::max(layer.top, v[1]);
      }
      for (const auto& m : deck.materials)
        if (m.block == region.block) layer.material = &m;
      ref.layers.push_back(layer);
    }
    double bottom = 1e300;
    for (const auto& l : ref.layers) bottom = std::min(bottom, l.bottom);
    ref.integrate(bottom, 1e-4);
    if (options.has("hand-over"))
      return verifyHandOver(deck, ref, options.number("phreatic-after", ref.phreatic), output,
                            relaxed_bound);
    {
      std::ofstream profile(output + "/k0_reference_profile.csv");
      profile << "y,stress_total_reference,liquid_pressure_reference\n";
      for (std::size_t k = 0; k < ref.y.size(); k += 100)
        profile << ref.y[k] << "," << ref.sigma[k] << "," << ref.pressure(ref.y[k]) << "\n";
    }

    argine::RunOptions run;
    run.output_directory = output;
    run.quiet = true;
    argine::Simulation simulation(deck, run);
    const Errors initial =
        compare(ref, deck, simulation.points(), output + "/k0_points_initial.csv");
    simulation.run();
    const Errors relaxed =
        compare(ref, deck, simulation.points(), output + "/k0_points_relaxed.csv");
    for (const auto& line : simulation.stageLog()) std::printf("  log: %s\n", line.c_str());

    std::printf("V6 K0 initialisation (%d points), max error / max |reference|:\n",
                simulation.points().count);
    std::printf("  after K0 procedure:   sigma'_yy %.3e   p_L %.3e   (bound %.3g)\n",
                initial.stress, initial.pressure, bound);
    std::printf("  after relaxation:     sigma'_yy %.3e   p_L %.3e   (bound %.3g)\n",
                relaxed.stress, relaxed.pressure, relaxed_bound);
    std::ofstream errors(output + "/k0_errors.csv");
    errors << "state,stress_error,pressure_error,bound\n"
           << "initial," << initial.stress << "," << initial.pressure << "," << bound << "\n"
           << "relaxed," << relaxed.stress << "," << relaxed.pressure << "," << relaxed_bound
           << "\n";
    const bool ok = initial.stress <= bound && initial.pressure <= bound &&
                    relaxed.stress <= relaxed_bound && relaxed.pressure <= relaxed_bound;
    std::printf("V6 K0 initialisation: %s\n", ok ? "PASSED" : "FAILED (bound exceeded)");
    return ok ? 0 : av::kExitBoundExceeded;
  });
}
