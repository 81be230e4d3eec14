#include "CriticalStepSearch.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>

#include "argine/core/Error.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/physics/ExplicitTwoPhaseSolver.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/PointInitialisation.hpp"
#include "argine/physics/TimeStepControl.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/simulation/Setup.hpp"
#include "argine/timestep/Criteria.hpp"

namespace argine::stability {

namespace {

using Clock = std::chrono::steady_clock;

template <class View>
std::vector<double> hostCopy(const View& view) {
  const auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
  return std::vector<double>(host.data(), host.data() + host.extent(0));
}

std::vector<double> verticalDisplacement(const MaterialPoints& points) {
  const auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.displacement);
  std::vector<double> values(host.extent(0));
  for (std::size_t p = 0; p < values.size(); ++p) values[p] = host(p, 1);
  return values;
}

double rms(const std::vector<double>& a, const std::vector<double>& b) {
  double sum = 0;
  for (std::size_t i = 0; i < a.size(); ++i) sum += (a[i] - b[i]) * (a[i] - b[i]);
  return a.empty() ? 0 : std::sqrt(sum / a.size());
}

}  // namespace

const char* verdictName(Verdict verdict) {
  switch (verdict) {
    case Verdict::Stable:
      return "stable";
    case Verdict::NonFinite:
      return "non-finite";
    case Verdict::EnergyBound:
      return "energy bound";
    case Verdict::EnergyGrowth:
      return "energy growth";
    case Verdict::Departure:
      return "departure";
  }
  return "unknown";
}

RunOutcome runFixedStep(const Deck& deck, Real dt, Real duration, Real kinetic_energy_limit,
                        bool track) {
  const auto start = Clock::now();
  RunOutcome outcome;
  Mesh mesh = loadMesh(deck);
  MaterialPoints points = seedPoints(deck, mesh);
  initialisePointState(deck.materials, points);
  // Points are never sorted (sort interval 0): index p is the same point in every run.
  ExplicitTwoPhaseSolver solver(mesh, points, deck.materials);
  solver.beginStage(deck.stages.front());

  // One controller per criterion, evaluated on the current states when tracking.
  std::vector<TimeStepControl> controls;
  const MaterialTable table(deck.materials);
  if (track) {
    for (const CriterionKind kind : kAllCriteria) {
      TimeStepSpec spec;
      spec.automatic = true;
      spec.safety_factor = 1;
      spec.criteria = {kind};
      controls.emplace_back(mesh);
      controls.back().configure(spec, deck.stages.front().mass_scaling, "tracking",
                                deck.stages.front().implicit_drag);
    }
    outcome.criteria_min.assign(controls.size(), std::numeric_limits<Real>::infinity());
  }
  auto sample = [&] {
    for (std::size_t c = 0; c < controls.size(); ++c)
      outcome.criteria_min[c] =
          std::min(outcome.criteria_min[c], controls[c].evaluate(points, table).critical_step);
    Real lo = 1, hi = 0;
    const auto s = points.saturation;
    Kokkos::parallel_reduce(
        "saturation_range", Kokkos::RangePolicy<ExecSpace>(0, points.count),
        KOKKOS_LAMBDA(const int p, Real& mn, Real& mx) {
          mn = s(p) < mn ? s(p) : mn;
          mx = s(p) > mx ? s(p) : mx;
        },
        Kokkos::Min<Real>(lo), Kokkos::Max<Real>(hi));
    outcome.saturation_min = std::min(outcome.saturation_min, lo);
    outcome.saturation_max = std::max(outcome.saturation_max, hi);
  };
  if (track) sample();

  const Real tolerance = 1e-12 * duration;
  try {
    while (duration - solver.time() > tolerance) {
      solver.step(std::min(dt, duration - solver.time()));
      ++outcome.steps;
      const StepDiagnostics& d = solver.diagnostics();
      const Real kinetic = d.kinetic_energy_solid + d.kinetic_energy_liquid;
      outcome.max_kinetic_energy = std::max(outcome.max_kinetic_energy, kinetic);
      if (track && outcome.steps % kTrackInterval == 0) sample();
      if (kinetic_energy_limit > 0 && kinetic > kinetic_energy_limit) {
        outcome.verdict = Verdict::EnergyGrowth;
        break;
      }
    }
  } catch (const RunError& error) {
    outcome.message = error.what();
    outcome.verdict = outcome.message.find("kinetic energy") != std::string::npos
                          ? Verdict::EnergyBound
                          : Verdict::NonFinite;
  }
  if (outcome.verdict == Verdict::Stable) {
    outcome.displacement = verticalDisplacement(points);
    outcome.pressure = hostCopy(points.pressure_liquid);
  }
  outcome.wall_seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return outcome;
}

Real departure(const RunOutcome& run, const RunOutcome& reference, Real load) {
  if (run.displacement.size() != reference.displacement.size() ||
      run.pressure.size() != reference.pressure.size())
    return std::numeric_limits<Real>::quiet_NaN();  // one of the two did not run through
  const std::vector<double> zero(reference.displacement.size(), 0.0);
  const double u_scale = rms(reference.displacement, zero);
  const double du = rms(run.displacement, reference.displacement);
  const double dp = rms(run.pressure, reference.pressure);
  return std::max(u_scale > 0 ? du / u_scale : 0.0, dp / load);
}

SearchResult findCriticalStep(const std::function<Deck(Real)>& make_deck, Real guess,
                              const SearchSettings& settings) {
  SearchResult result;
  result.duration = settings.steps_of_guess * guess;
  auto account = [&](const RunOutcome& run) {
    ++result.runs;
    result.steps += run.steps;
    result.wall_seconds += run.wall_seconds;
  };

  // The converged reference: a small step, halved until it runs through.
  RunOutcome reference;
  Real dt_ref = settings.reference_fraction * guess;
  for (int attempt = 0; attempt < settings.reference_halvings; ++attempt) {
    reference = runFixedStep(make_deck(dt_ref), dt_ref, result.duration, 0, true);
    account(reference);
    if (reference.verdict == Verdict::Stable) break;
    dt_ref /= 2;
  }
  if (reference.verdict != Verdict::Stable)
    throw RunError("no stable reference down to dt = " + std::to_string(dt_ref) +
                   " s: " + reference.message);
  result.reference_step = dt_ref;
  result.reference_kinetic_energy = reference.max_kinetic_energy;
  result.seconds_per_step = reference.wall_seconds / std::max<long>(reference.steps, 1);
  result.criteria_min = reference.criteria_min;
  result.saturation_min = reference.saturation_min;
  result.saturation_max = reference.saturation_max;
  const Real energy_limit = settings.energy_factor * reference.max_kinetic_energy;

  // Judges a step; stable runs also give their departure.
  auto judge = [&](Real dt, Real& departure_of_run) {
    RunOutcome run = runFixedStep(make_deck(dt), dt, result.duration, energy_limit);
    account(run);
    departure_of_run = 0;
    if (run.verdict != Verdict::Stable) return run.verdict;
    departure_of_run = departure(run, reference, settings.load);
    return departure_of_run > settings.departure_tolerance ? Verdict::Departure : Verdict::Stable;
  };

  Real stable = 0, unstable = 0, stable_departure = 0;
  Verdict reason = Verdict::Stable;
  auto record = [&](Real dt) {
    Real d = 0;
    const Verdict verdict = judge(dt, d);
    if (verdict == Verdict::Stable) {
      stable = dt;
      stable_departure = d;
    } else {
      unstable = dt;
      reason = verdict;
    }
    return verdict == Verdict::Stable;
  };
  // The reference is the stable start (by construction: it ran through, and its own kinetic
  // energy is within the growth bound).
  stable = dt_ref;
  // Climb the ladder to the first instability.
  unstable = 0;
  for (int i = 0; i < settings.max_rungs && unstable == 0; ++i) record(stable * settings.ladder);
  if (unstable > 0)
    while (unstable / stable > 1 + settings.relative_width) record(std::sqrt(stable * unstable));
  result.stable_step = stable;
  result.unstable_step = unstable;
  result.unstable_reason = reason;
  result.departure_at_stable = stable_departure;
  return result;
}

}  // namespace argine::stability
