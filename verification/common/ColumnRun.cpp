#include "ColumnRun.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "argine/core/Error.hpp"
#include "argine/physics/PointInitialisation.hpp"
#include "argine/simulation/Setup.hpp"

namespace argine::verification {

namespace {

using Clock = std::chrono::steady_clock;

double secondsSince(Clock::time_point start) {
  return std::chrono::duration<double>(Clock::now() - start).count();
}

template <class View>
std::vector<double> column(const View& view, int component) {
  const auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
  std::vector<double> values(host.extent(0));
  for (std::size_t p = 0; p < values.size(); ++p) values[p] = host(p, component);
  return values;
}

template <class View>
std::vector<double> scalar(const View& view) {
  const auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), view);
  return std::vector<double>(host.data(), host.data() + host.extent(0));
}

}  // namespace

Deck columnDeck(const Deck& deck, int elements) {
  if (!deck.mesh.generate || deck.mesh.generator.kind != GeneratorSpec::Kind::Rectangle)
    throw InputError(deck.path + ": Mesh/Generate",
                     "a verification column needs a generated rectangle mesh");
  if (elements < 1) throw InputError("elements", "at least one element is needed");
  Deck column = deck;
  GeneratorSpec& box = column.mesh.generator;
  const Real height = box.upper_right[1] - box.lower_left[1];
  box.element_size = height / elements;
  box.upper_right[0] = box.lower_left[0] + box.element_size;
  return column;
}

ColumnRun::ColumnRun(const Deck& deck) : deck_(deck) {
  const auto start = Clock::now();
  if (deck_.stages.empty()) throw InputError(deck_.path, "the deck has no stage");
  mesh_ = loadMesh(deck_);
  points_ = seedPoints(deck_, mesh_);
  initialisePointState(deck_.materials, points_);
  solver_ = std::make_unique<ExplicitTwoPhaseSolver>(mesh_, points_, deck_.materials);
  solver_->beginStage(deck_.stages.front());
  wall_seconds_ = secondsSince(start);
}

ColumnRun::~ColumnRun() = default;

void ColumnRun::advanceTo(Real time) {
  const auto start = Clock::now();
  // A remainder below this is round-off of the time sum, not a step to take.
  const Real tolerance = 1e-12 * std::max<Real>(std::fabs(time), 1);
  while (time - solver_->time() > tolerance) {
    const Real chosen = solver_->chooseTimeStep().time_step;
    const Real remaining = time - solver_->time();
    const bool landing = chosen >= remaining;
    const Real dt = landing ? remaining : chosen;
    solver_->step(dt);
    if (!landing) {
      smallest_step_ = smallest_step_ > 0 ? std::min(smallest_step_, dt) : dt;
      largest_step_ = std::max(largest_step_, dt);
    }
    ++steps_;
  }
  solver_->setTime(time);  // remove the round-off of the time sum
  wall_seconds_ += secondsSince(start);
}

ColumnProfile ColumnRun::profile() const {
  ColumnProfile profile;
  const auto element = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points_.element);
  profile.element.assign(element.data(), element.data() + element.extent(0));
  profile.initial_y = column(points_.initial_position, 1);
  profile.y = column(points_.position, 1);
  profile.pressure = scalar(points_.pressure_liquid);
  profile.saturation = scalar(points_.saturation);
  profile.displacement = column(points_.displacement, 1);
  profile.strain_yy = column(points_.strain, YY);
  profile.stress_yy = column(points_.stress_effective, YY);
  profile.volume = scalar(points_.volume);
  profile.liquid_mass = scalar(points_.mass_liquid);
  return profile;
}

}  // namespace argine::verification
