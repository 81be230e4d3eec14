// V5 critical time step study (VERIFICATION.md V5, doc/stability.md, thesis Ch. 4 Sec. 7.3).
// For every case of a set (StabilityCases.hpp) finds the empirical critical step of the
// loaded column by bisection (CriticalStepSearch.hpp) and writes it with the step every
// criterion of timestep/Criteria.hpp predicts, one CSV row per case. The cases can be split
// over processes (--shard i --shards m takes every m-th case from i). With --check NAME the
// driver fails (exit 1) when criterion NAME times --safety (default 1: the criterion alone)
// predicts a step above the empirical critical step of a case, or when a case has no stable
// step at all (no criterion can be safe there): the safety test of the production criterion.
#include <cctype>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <string>
#include <vector>

#include "CommandLine.hpp"
#include "CriticalStepSearch.hpp"
#include "ResultTable.hpp"
#include "StabilityCases.hpp"
#include "VerificationMain.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"

namespace av = argine::verification;
namespace st = argine::stability;
using argine::Real;

namespace {

constexpr const char* kUsage =
    "argine_stability [--set saturation|permeability|mesh|all|quick|realistic]\n"
    "  [--shard I --shards M] [--output DIR] [--steps 2000] [--tolerance 1.0]\n"
    "  [--width 0.02] [--check CRITERION [--safety 1]] [--deck FILE] [--scan F1,F2,...]\n"
    "--scan: instead of the search, runs each case at F x the first guess and prints the\n"
    "verdict, departure and largest kinetic energy of each run (to look at one case).\n"
    "CRITERION: a criterion name of timestep/Criteria.hpp, spaces as '_' (e.g. coupled).\n";

/// "CFL dry" -> "cfl_dry": CSV column and --check names.
std::string slug(const std::string& name) {
  std::string s;
  for (const char c : name)
    s += c == ' ' ? '_' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  return s;
}

/// Prints verdict, departure and largest kinetic energy at each multiple of the guess.
void scanCase(const argine::Deck& base, const st::StabilityCase& c, Real guess,
              const std::vector<double>& factors, const st::SearchSettings& settings) {
  const Real duration = settings.steps_of_guess * guess;
  const Real dt_ref = settings.reference_fraction * guess;
  const st::RunOutcome reference =
      st::runFixedStep(st::caseDeck(base, c, dt_ref), dt_ref, duration, 0);
  std::cout << st::soilName(c) << " n=" << c.porosity << " E=" << c.youngs_modulus
            << " S_L=" << c.saturation << ": guess " << guess << " s, duration " << duration
            << " s, reference " << st::verdictName(reference.verdict) << " KE_max "
            << reference.max_kinetic_energy << "\n";
  for (const double f : factors) {
    const Real dt = f * guess;
    const st::RunOutcome run = st::runFixedStep(st::caseDeck(base, c, dt), dt, duration, 0, true);
    std::cout << "  dt = " << dt << " (" << f << " x guess): " << st::verdictName(run.verdict)
              << ", " << run.steps << " steps, KE_max " << run.max_kinetic_energy << ", S_L in ["
              << run.saturation_min << ", " << run.saturation_max << "]";
    if (run.verdict == st::Verdict::Stable)
      std::cout << ", departure " << st::departure(run, reference, settings.load);
    else if (!run.message.empty())
      std::cout << "\n    " << run.message;
    std::cout << "\n";
  }
}

}  // namespace

int main(int argc, char** argv) {
  return av::runVerification(argc, argv, [](int argc, char** argv) {
    const av::CommandLine options(argc, argv,
                                  {"set", "shard", "shards", "output", "steps", "tolerance",
                                   "width", "check", "safety", "deck", "scan", "help"});
    if (options.has("help")) {
      std::cout << kUsage;
      return 0;
    }
    const std::string set = options.text("set", "all");
    const int shard = static_cast<int>(options.number("shard", 0));
    const int shards = static_cast<int>(options.number("shards", 1));
    const std::string output = options.text("output", "");
    const std::string check = options.text("check", "");
    const Real safety = options.number("safety", 1.0);
    st::SearchSettings settings;
    settings.steps_of_guess = options.number("steps", settings.steps_of_guess);
    settings.departure_tolerance = options.number("tolerance", settings.departure_tolerance);
    settings.relative_width = options.number("width", settings.relative_width);
    const argine::Deck base = argine::readDeck(
        options.text("deck", std::string(ARGINE_STABILITY_DECK_DIR) + "/stability_column.yaml"));

    int check_index = -1;
    std::vector<std::string> columns = {"family",
                                        "soil",
                                        "porosity",
                                        "youngs_modulus_Pa",
                                        "permeability_m2",
                                        "conductivity_m_per_s",
                                        "liquid_bulk_modulus_Pa",
                                        "element_size_m",
                                        "target_saturation",
                                        "suction_Pa",
                                        "saturation",
                                        "dSds_per_Pa",
                                        "duration_s",
                                        "dt_c_s",
                                        "dt_unstable_s",
                                        "unstable_reason",
                                        "departure_at_dt_c",
                                        "reference_dt_s",
                                        "runs",
                                        "steps",
                                        "wall_s",
                                        "seconds_per_step"};
    int k = 0;
    for (const argine::CriterionKind kind : argine::kAllCriteria) {
      columns.push_back("crit_" + slug(argine::criterionName(kind)));
      if (slug(argine::criterionName(kind)) == check) check_index = k;
      ++k;
    }
    columns.push_back("crit_mieremet_saturated");
    for (const argine::CriterionKind kind : argine::kAllCriteria)
      columns.push_back("run_" + slug(argine::criterionName(kind)));
    columns.push_back("saturation_min_run");
    columns.push_back("saturation_max_run");
    if (!check.empty() && check_index < 0) {
      std::cerr << "--check: no criterion named '" << check << "'\n" << kUsage;
      return av::kExitCannotRun;
    }
    av::ResultTable table(columns);

    const std::vector<st::StabilityCase> cases = st::caseSet(set);
    int failures = 0;
    for (std::size_t i = static_cast<std::size_t>(shard); i < cases.size();
         i += static_cast<std::size_t>(shards)) {
      const st::StabilityCase& c = cases[i];
      const argine::Deck probe = st::caseDeck(base, c, 1.0);
      const argine::CriterionInput in = st::criterionInputOf(probe);
      const std::vector<Real> predicted = st::predictedSteps(in);
      const Real guess = st::searchGuess(in);
      if (options.has("scan")) {
        scanCase(base, c, guess, options.numbers("scan", {}), settings);
        continue;
      }
      st::SearchResult r;
      std::string failure;
      try {
        r = st::findCriticalStep([&](Real dt) { return st::caseDeck(base, c, dt); }, guess,
                                 settings);
      } catch (const argine::RunError& error) {
        // No stable run at all: no critical step (dt_c = 0), the reason in the log.
        failure = error.what();
        std::cout << "[" << i + 1 << "/" << cases.size() << "] " << c.family << " "
                  << st::soilName(c) << " n=" << c.porosity << " E=" << c.youngs_modulus
                  << " S_L=" << in.saturation << ": NO STABLE STEP: " << failure << "\n";
        r.criteria_min.assign(predicted.size(), std::nan(""));
        r.saturation_min = r.saturation_max = std::nan("");
      }
      table.row()
          .add(c.family)
          .add(st::soilName(c))
          .add(c.porosity)
          .add(c.youngs_modulus)
          .add(c.permeability)
          .add(in.hydraulic_conductivity)
          .add(c.liquid_bulk_modulus)
          .add(in.element_size)
          .add(c.saturation)
          .add(st::caseSuction(c))
          .add(in.saturation)
          .add(in.saturation_suction_derivative)
          .add(r.duration)
          .add(r.stable_step)
          .add(r.unstable_step)
          .add(failure.empty() ? st::verdictName(r.unstable_reason) : "no stable step")
          .add(r.departure_at_stable)
          .add(r.reference_step)
          .add(r.runs)
          .add(r.steps)
          .add(r.wall_seconds)
          .add(r.seconds_per_step);
      for (const Real p : predicted) table.add(p);
      table.add(st::saturatedMieremetStep(in));
      for (const Real p : r.criteria_min) table.add(p);
      table.add(r.saturation_min).add(r.saturation_max);
      std::cout << std::setprecision(4) << "[" << i + 1 << "/" << cases.size() << "] " << c.family
                << " " << st::soilName(c) << " n=" << c.porosity << " E=" << c.youngs_modulus
                << " kappa=" << c.permeability << " L=" << in.element_size
                << " S_L=" << in.saturation << ": dt_c in [" << r.stable_step << ", "
                << r.unstable_step << "] (" << st::verdictName(r.unstable_reason) << "), guess "
                << guess << ", " << r.runs << " runs, " << r.steps << " steps, " << r.wall_seconds
                << " s\n"
                << std::flush;
      // The step an automatic run with the criterion would take at most: its minimum over
      // the states of the (converged) reference run, not only the initial state.
      const Real production =
          check_index < 0 ? 0
                          : safety * std::min(predicted[check_index], r.criteria_min[check_index]);
      if (check_index >= 0 && !failure.empty()) {
        std::cout << "FAIL: no stable step, so no criterion is safe here\n";
        ++failures;
      } else if (check_index >= 0 && !(production <= r.stable_step)) {
        std::cout << "FAIL: criterion " << check << " x " << safety << " allows " << production
                  << " s > empirical critical step " << r.stable_step << " s\n";
        ++failures;
      }
    }
    const std::string file =
        "stability_" + set + "_" + std::to_string(shard) + "of" + std::to_string(shards) + ".csv";
    table.writeCsv(av::pathIn(output, file));
    std::cout << "wrote " << av::pathIn(output, file) << "\n";
    if (check_index >= 0)
      std::cout << (failures ? "V5 check FAILED" : "V5 check passed") << " (" << check << ")\n";
    return failures ? av::kExitBoundExceeded : 0;
  });
}
