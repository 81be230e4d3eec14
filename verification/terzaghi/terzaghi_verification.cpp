// V1 Terzaghi consolidation (doc/verification.md, VERIFICATION.md V1): runs the deck's
// column at several resolutions, stops exactly at the isochrone times T = 0.05 ... 1 and at
// denser times for the degree of consolidation, compares p_L with the series solution
// (TerzaghiReference.hpp), prints the error table, writes CSV files and exits non-zero when
// a bound is exceeded:
//   - error <= bound (3 %) at every isochrone on the bound mesh (40 elements);
//   - the error falls with every refinement (10 -> 20 -> 40 -> 80 elements).
// The error is the larger of the two relative L2 norms of ProfileNorms.hpp: against what is
// left (||p_ref||, strict late) and against what has changed (||p0 - p_ref||, strict early).
#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>

#include "ColumnRun.hpp"
#include "CommandLine.hpp"
#include "ProfileNorms.hpp"
#include "ResultTable.hpp"
#include "StageOverrides.hpp"
#include "TerzaghiReference.hpp"
#include "VerificationMain.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"

namespace av = argine::verification;
using argine::Deck;

namespace {

constexpr const char* kUsage =
    "terzaghi_verification [--deck FILE] [--elements 10,20,40,80] [--bound-elements 40]\n"
    "  [--bound 0.03] [--factors 0.05,0.1,0.2,0.5,1] [--output DIR] [--mass-scaling F]\n"
    "  [--safety S] [--damping A] [--mass-balance complete|simplified] [--tag NAME]\n"
    "  [--no-bounds] [--transfer FLIP|APIC]\n"
    "CSV files: <output>/<tag>_errors.csv, _profiles.csv, _consolidation.csv (tag: terzaghi).\n";

/// The reference's parameters, read from the deck so the two cannot disagree.
av::TerzaghiParameters parametersOfDeck(const Deck& deck) {
  if (deck.materials.size() != 1 || deck.stages.empty())
    throw argine::InputError(deck.path, "V1 expects one material and at least one stage");
  const argine::MaterialSpec& soil = deck.materials.front();
  av::TerzaghiParameters p;
  const auto& box = deck.mesh.generator;
  p.height = box.upper_right[1] - box.lower_left[1];
  const double E = soil.solid.youngs_modulus, nu = soil.solid.poisson_ratio;
  p.constrained_modulus = E * (1 - nu) / ((1 + nu) * (1 - 2 * nu));
  p.porosity = soil.porosity;
  p.liquid_bulk_modulus = soil.liquid.bulk_modulus;
  p.liquid_density = soil.liquid.density;
  p.conductivity = soil.conductivity.saturated_conductivity;
  p.gravity = argine::kStandardGravity;
  bool loaded = false;
  for (const auto& boundary : deck.stages.front().boundaries)
    if (boundary.kind == argine::BoundaryKind::Traction) {
      p.load = -boundary.traction[1];  // downward traction = compressive total stress
      loaded = true;
    }
  if (!loaded) throw argine::InputError(deck.path, "V1 expects a traction on the top");
  return p;
}

/// Checks the series against classical values of U(T) (Terzaghi 1943, Table; e.g. Craig's
/// Soil Mechanics Fig. 7.18) and hand-evaluated p/p0: returns false when they disagree.
bool referenceSelfCheck(const av::TerzaghiReference& reference) {
  struct Value {
    double T, U;
  };
  // U = sqrt(4T/pi) for U < 0.6: T = 0.05 -> 0.2523; then tabulated 0.2 -> 0.5041,
  // 0.5 -> 0.7640, 1 -> 0.9313.
  const Value table[] = {{0.05, 0.2523}, {0.2, 0.5041}, {0.5, 0.7640}, {1.0, 0.9313}};
  bool ok = true;
  for (const Value& v : table)
    if (std::fabs(reference.degreeOfConsolidation(v.T) - v.U) > 1e-4) {
      std::cerr << "reference self-check: U(" << v.T
                << ") = " << reference.degreeOfConsolidation(v.T) << ", expected " << v.U << "\n";
      ok = false;
    }
  // p/p0 at the base, T = 1: (4/pi)(e^{-pi^2/4} - e^{-9 pi^2/4}/3 + ...) = 1.27324 x 0.08480
  // = 0.10798 (the second term is 7.6e-11).
  const double base = reference.normalisedPressure(0.0, 1.0);
  if (std::fabs(base - 0.10798) > 1e-4) {
    std::cerr << "reference self-check: p/p0(0, T=1) = " << base << ", expected 0.10798\n";
    ok = false;
  }
  // At the drained top p = 0 for every T > 0.
  if (std::fabs(reference.normalisedPressure(reference.parameters().height, 0.05)) > 1e-12) {
    std::cerr << "reference self-check: p(h) != 0\n";
    ok = false;
  }
  return ok;
}

/// Merged, sorted sample factors: the isochrones plus a log-spaced set for U(T).
std::vector<double> sampleFactors(const std::vector<double>& isochrones) {
  std::vector<double> factors = isochrones;
  const double last = *std::max_element(isochrones.begin(), isochrones.end());
  for (double T = 1e-3; T < last; T *= std::pow(10.0, 0.1)) factors.push_back(T);
  std::sort(factors.begin(), factors.end());
  factors.erase(std::unique(factors.begin(), factors.end(),
                            [](double a, double b) { return std::fabs(a - b) < 1e-9 * b; }),
                factors.end());
  return factors;
}

bool isIsochrone(double T, const std::vector<double>& isochrones) {
  for (double t : isochrones)
    if (std::fabs(t - T) < 1e-9 * t) return true;
  return false;
}

/// Settlement (m, compression positive) = -integral of the vertical strain over the
/// column: each point holds V / width of the height.
double settlementOf(const av::ColumnProfile& profile, double width) {
  double sum = 0;
  for (std::size_t p = 0; p < profile.volume.size(); ++p)
    sum -= profile.strain_yy[p] * profile.volume[p] / width;
  return sum;
}

struct RunResult {
  int elements = 0;
  std::map<double, av::ProfileError> errors;  ///< per isochrone factor T
  long steps = 0;
  double wall_seconds = 0;
};

}  // namespace

int main(int argc, char** argv) {
  return av::runVerification(argc, argv, [](int argc, char** argv) {
    const av::CommandLine options(
        argc, argv,
        {"deck", "elements", "bound-elements", "bound", "factors", "output", "mass-scaling",
         "safety", "damping", "mass-balance", "tag", "no-bounds", "transfer", "help"});
    if (options.has("help")) {
      std::cout << kUsage;
      return 0;
    }
    Deck deck = argine::readDeck(options.text("deck", ARGINE_TERZAGHI_DECK));
    av::applyTransferOption(options, deck);
    argine::StageSpec& stage = deck.stages.front();
    if (options.has("mass-scaling")) stage.mass_scaling = options.number("mass-scaling", 1);
    if (options.has("safety"))
      stage.time_step.safety_factor = options.number("safety", stage.time_step.safety_factor);
    if (options.has("damping")) stage.local_damping = options.number("damping", 0);
    argine::MaterialSpec& soil = deck.materials.front();
    if (options.has("mass-balance")) {
      const std::string form = options.text("mass-balance", "");
      if (form != "complete" && form != "simplified")
        throw std::invalid_argument("--mass-balance takes complete or simplified");
      soil.mass_balance = form == "complete" ? argine::MassBalanceForm::Complete
                                             : argine::MassBalanceForm::Simplified;
    }
    const std::string tag = options.text("tag", "terzaghi");
    const std::string form =
        soil.mass_balance == argine::MassBalanceForm::Complete ? "complete" : "simplified";

    const std::vector<int> elements = options.integers("elements", {10, 20, 40, 80});
    const int bound_elements = static_cast<int>(options.number("bound-elements", 40));
    const double bound = options.number("bound", 0.03);
    const std::vector<double> isochrones = options.numbers("factors", {0.05, 0.1, 0.2, 0.5, 1});
    const std::string output = options.text("output", "");

    const av::TerzaghiReference reference(parametersOfDeck(deck));
    if (!referenceSelfCheck(reference)) return av::kExitBoundExceeded;
    const double p0 = reference.initialPressure();
    std::cout << std::setprecision(6)
              << "V1 Terzaghi: c_v = " << reference.consolidationCoefficient()
              << " m2/s, p0 = " << p0 << " Pa, T = 1 at t = " << reference.timeOfFactor(1)
              << " s; mass scaling " << stage.mass_scaling << ", local damping "
              << stage.local_damping << ", safety factor " << stage.time_step.safety_factor << ", "
              << form << " mass balance\n";

    av::ResultTable errors({"case", "form", "elements", "points", "T", "t_s", "error",
                            "error_relative", "error_of_change", "max_abs_error_over_p0",
                            "error_element_means", "steps", "wall_s", "dt_min_s", "dt_max_s"});
    av::ResultTable profiles({"elements", "T", "y0_m", "p_num_over_p0", "p_ref_over_p0"});
    av::ResultTable consolidation({"elements", "T", "t_s", "U_ref", "U_settlement", "U_pressure",
                                   "settlement_m", "settlement_ref_m", "wall_s"});
    const std::vector<double> factors = sampleFactors(isochrones);
    std::vector<RunResult> results;

    for (const int n : elements) {
      const Deck column = av::columnDeck(deck, n);
      av::ColumnRun run(column);
      const double width = column.mesh.generator.element_size;
      RunResult result;
      result.elements = n;
      for (const double T : factors) {
        run.advanceTo(reference.timeOfFactor(T));
        const av::ColumnProfile profile = run.profile();
        const std::size_t count = profile.pressure.size();
        std::vector<double> numerical(count), exact(count), initial(count, 1.0);
        double mean_pressure = 0, total_volume = 0;
        for (std::size_t p = 0; p < count; ++p) {
          numerical[p] = profile.pressure[p] / p0;
          exact[p] = reference.normalisedPressure(profile.initial_y[p], T);
          mean_pressure += profile.pressure[p] * profile.volume[p];
          total_volume += profile.volume[p];
        }
        mean_pressure /= total_volume;
        const double settlement = settlementOf(profile, width);
        const double w0 = reference.immediateSettlement(), w1 = reference.finalSettlement();
        consolidation.row()
            .add(n)
            .add(T)
            .add(run.time())
            .add(reference.degreeOfConsolidation(T))
            .add((settlement - w0) / (w1 - w0))
            .add(1 - mean_pressure / p0)
            .add(settlement)
            .add(reference.settlement(T))
            .add(run.wallSeconds());
        if (!isIsochrone(T, isochrones)) continue;
        const av::ProfileError error = av::profileError(numerical, exact, initial, profile.volume);
        result.errors[T] = error;
        errors.row()
            .add("V1 terzaghi")
            .add(form)
            .add(n)
            .add(run.pointCount())
            .add(T)
            .add(run.time())
            .add(error.governing())
            .add(error.relative)
            .add(error.of_change)
            .add(error.max_abs)
            .add(av::elementMeanError(numerical, exact, profile.volume, profile.element))
            .add(run.steps())
            .add(run.wallSeconds())
            .add(run.smallestStep())
            .add(run.largestStep());
        for (std::size_t p = 0; p < count; ++p)
          profiles.row().add(n).add(T).add(profile.initial_y[p]).add(numerical[p]).add(exact[p]);
      }
      result.steps = run.steps();
      result.wall_seconds = run.wallSeconds();
      results.push_back(result);
      std::cout << "  " << n << " elements: " << run.steps() << " steps (dt " << run.smallestStep()
                << " .. " << run.largestStep() << " s), " << run.wallSeconds() << " s wall\n"
                << std::flush;
    }

    std::cout << "\n";
    errors.print(std::cout);
    errors.writeCsv(av::pathIn(output, tag + "_errors.csv"));
    profiles.writeCsv(av::pathIn(output, tag + "_profiles.csv"));
    consolidation.writeCsv(av::pathIn(output, tag + "_consolidation.csv"));

    // Observed order between successive meshes, per isochrone and for the RMS over them.
    int failures = 0;
    auto rms = [&](const RunResult& r) {
      double sum = 0;
      for (const auto& [T, e] : r.errors) sum += e.governing() * e.governing();
      return std::sqrt(sum / r.errors.size());
    };
    std::cout << "\nobserved order (error = max(relative, of change), element size halved):\n";
    for (std::size_t k = 1; k < results.size(); ++k) {
      const RunResult &coarse = results[k - 1], &fine = results[k];
      const double ratio = static_cast<double>(fine.elements) / coarse.elements;
      std::cout << "  " << coarse.elements << " -> " << fine.elements << ":";
      for (const auto& [T, e] : fine.errors)
        std::cout << " T=" << T << ": "
                  << av::observedOrder(coarse.errors.at(T).governing(), e.governing(), ratio);
      std::cout << "; RMS over T: " << av::observedOrder(rms(coarse), rms(fine), ratio) << "\n";
      if (!(rms(fine) < rms(coarse))) {
        std::cout << "  FAIL: the error does not fall from " << coarse.elements << " to "
                  << fine.elements << " elements (RMS " << rms(coarse) << " -> " << rms(fine)
                  << ")\n";
        ++failures;
      }
    }
    for (const RunResult& r : results) {
      if (r.elements != bound_elements) continue;
      for (const auto& [T, e] : r.errors)
        if (!(e.governing() <= bound)) {
          std::cout << "FAIL: error " << e.governing() << " (relative " << e.relative
                    << ", of change " << e.of_change << ") > " << bound << " at T = " << T << " on "
                    << r.elements << " elements\n";
          ++failures;
        }
    }
    if (options.has("no-bounds")) return 0;
    std::cout << (failures ? "V1 FAILED" : "V1 passed") << " (" << form << " mass balance)\n";
    return failures ? av::kExitBoundExceeded : 0;
  });
}
