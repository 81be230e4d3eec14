#include "argine/simulation/RelaxationMonitor.hpp"

#include <algorithm>
#include <limits>

namespace argine {

bool RelaxationMonitor::add(Real time, Real kinetic_energy, Real stored_energy) {
  ++steps_;
  stored_ = stored_energy;
  peak_ = std::max(peak_, kinetic_energy);
  // Monotonic queue: the front is the largest value of the last W seconds.
  while (!window_.empty() && window_.back().second <= kinetic_energy) window_.pop_back();
  window_.emplace_back(time, kinetic_energy);
  while (window_.front().first < time - spec_.window) window_.pop_front();
  relaxed_ = time - start_ >= spec_.window && ratio() <= spec_.kinetic_energy_ratio;
  return relaxed_;
}

Real RelaxationMonitor::ratio() const {
  if (window_.empty()) return 1;
  const Real largest = window_.front().second;
  if (!(largest > 0)) return 0;
  if (!(stored_ > 0)) return std::numeric_limits<Real>::infinity();
  return largest / stored_;
}

}  // namespace argine
