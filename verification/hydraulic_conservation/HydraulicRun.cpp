#include "HydraulicRun.hpp"

#include <algorithm>
#include <chrono>
#include <ctime>

#include "argine/init/Initialisation.hpp"
#include "argine/physics/PointInitialisation.hpp"
#include "argine/simulation/Setup.hpp"

namespace argine::verification {

namespace {
double now() {
  using Clock = std::chrono::steady_clock;
  return std::chrono::duration<double>(Clock::now().time_since_epoch()).count();
}
/// Processor time of this process (s): the cost of a run on a machine shared with others.
double processorSeconds() {
  return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}
}  // namespace

Real liquidMass(const MaterialPoints& points) {
  const auto mass = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.mass_liquid);
  Real sum = 0;
  for (int p = 0; p < points.count; ++p) sum += mass(p);
  return sum;
}

HydraulicRun::HydraulicRun(const Deck& deck, const Initialiser& initialise) : deck_(deck) {
  const double start = now(), cpu_start = processorSeconds();
  mesh_ = loadMesh(deck_);
  points_ = seedPoints(deck_, mesh_);
  (void)initialisePoints(deck_, mesh_, points_);  // the deck's Initialisation, as argine run
  if (initialise) initialise(deck_.materials, points_);
  solver_ = std::make_unique<ExplicitTwoPhaseSolver>(mesh_, points_, deck_.materials);
  solver_->setSortInterval(ExplicitTwoPhaseSolver::kRecommendedSortInterval);
  solver_->beginStage(deck_.stages.front());
  for (const auto& condition : solver_->hydraulicConditions().conditions())
    inflow_[condition.name] = 0;
  initial_liquid_mass_ = liquidMass(points_);
  wall_seconds_ = now() - start;
  cpu_seconds_ = processorSeconds() - cpu_start;
}

HydraulicRun::~HydraulicRun() = default;

void HydraulicRun::advanceTo(Real time) {
  const double start = now(), cpu_start = processorSeconds();
  const Real tolerance = 1e-12 * std::max<Real>(time, 1);
  while (solver_->time() < time - tolerance) {
    const Real dt = std::min(solver_->chooseTimeStep().time_step, time - solver_->time());
    solver_->step(dt);
    ++steps_;
    const auto& conditions = solver_->hydraulicConditions().conditions();
    const auto& volumes = solver_->boundaryFluxVolumes();
    for (std::size_t c = 0; c < conditions.size(); ++c) inflow_[conditions[c].name] += volumes[c];
  }
  wall_seconds_ += now() - start;
  cpu_seconds_ += processorSeconds() - cpu_start;
}

Real HydraulicRun::inflow(const std::string& name) const {
  const auto found = inflow_.find(name);
  return found == inflow_.end() ? 0 : found->second;
}

Real HydraulicRun::totalInflow() const {
  Real sum = 0;
  for (const auto& entry : inflow_) sum += entry.second;
  return sum;
}

Real HydraulicRun::storageChange() const {
  return (liquidMass(points_) - initial_liquid_mass_) / solver_->referenceLiquidDensity();
}

}  // namespace argine::verification
