#include "argine/simulation/RunGuards.hpp"

#include <cmath>
#include <sstream>

#include "argine/core/Error.hpp"

namespace argine {

namespace {

std::string at(const GuardPlace& place) {
  std::ostringstream out;
  out << "at t = " << place.time << " s (step " << place.step << ", stage '" << place.stage << "')";
  return out.str();
}

/// Host copy of one point: "point <id> at (x, y)".
std::string pointText(const MaterialPoints& points, int index) {
  const auto one = std::make_pair(index, index + 1);
  const auto id =
      Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), Kokkos::subview(points.id, one));
  const auto x = Kokkos::create_mirror_view_and_copy(
      Kokkos::HostSpace(), Kokkos::subview(points.position, one, Kokkos::ALL));
  std::ostringstream out;
  out << "point id " << id(0) << " at (" << x(0, 0) << ", " << x(0, 1) << ")";
  return out.str();
}

}  // namespace

void RunGuards::beginStage(Real storage, Real inflow, Real initial_volume) {
  storage_0_ = storage;
  inflow_0_ = inflow;
  initial_volume_ = initial_volume;
  peak_ratio_ = -1;
}

std::string RunGuards::checkMassBalance(Real storage, Real inflow, const GuardPlace& place) {
  if (mass_warned_ || !(initial_volume_ > 0)) return "";
  const Real error = (storage - storage_0_) - (inflow - inflow_0_);
  const Real relative = std::abs(error) / initial_volume_;
  if (!(relative > spec_.mass_balance_bound)) return "";
  mass_warned_ = true;
  std::ostringstream out;
  out << "liquid mass balance error " << relative << " of the initial liquid volume exceeds "
      << "Guards/Mass Balance Bound " << spec_.mass_balance_bound << " " << at(place)
      << ": storage change " << storage - storage_0_ << " m3/m, net inflow " << inflow - inflow_0_
      << " m3/m, initial liquid volume " << initial_volume_ << " m3/m (warned once)";
  return out.str();
}

std::string RunGuards::checkKineticEnergy(Real kinetic, Real scale, const GuardPlace& place) {
  if (scale > 0 && kinetic / scale > peak_ratio_) {
    peak_ratio_ = kinetic / scale;
    peak_kinetic_ = kinetic;
    peak_scale_ = scale;
    peak_place_ = place;
  }
  if (energy_warned_ || !(scale > 0)) return "";
  const Real bound = spec_.kinetic_energy_bound * scale;
  if (!(kinetic > bound)) return "";
  energy_warned_ = true;
  std::ostringstream out;
  out << "kinetic energy " << kinetic << " J/m exceeds Guards/Kinetic Energy Bound "
      << spec_.kinetic_energy_bound << " x the stage's energy scale " << scale << " J/m = " << bound
      << " J/m " << at(place) << " (warned once)";
  return out.str();
}

std::string RunGuards::kineticEnergyPeak(const std::string& stage) const {
  if (!(peak_ratio_ >= 0)) return "";
  std::ostringstream out;
  out << "stage '" << stage << "': largest kinetic energy " << peak_kinetic_ << " J/m "
      << at(peak_place_) << " = " << peak_ratio_ << " x the energy scale " << peak_scale_
      << " J/m (Guards/Kinetic Energy Bound warns above " << spec_.kinetic_energy_bound
      << " x, the run stops above 1 x)";
  return out.str();
}

std::string RunGuards::handleLeavingPoints(MaterialPoints& points, const GuardPlace& place) {
  const auto element = points.element;
  const auto velocity_solid = points.velocity_solid;
  const auto velocity_liquid = points.velocity_liquid;
  const auto affine_solid = points.affine_velocity_solid;
  const auto affine_liquid = points.affine_velocity_liquid;
  int outside = 0, first = points.count;
  Kokkos::parallel_reduce(
      "guard_count_outside", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, int& count, int& lowest) {
        if (element(p) >= 0) return;
        ++count;
        // The first point not yet removed (removed ones have zero velocities).
        const bool moving = velocity_solid(p, 0) != 0 || velocity_solid(p, 1) != 0 ||
                            velocity_liquid(p, 0) != 0 || velocity_liquid(p, 1) != 0;
        if (moving && p < lowest) lowest = p;
      },
      outside, Kokkos::Min<int>(first));
  // Points outside stay outside (no shape functions: they do not move), so the count only
  // grows; the new ones are those beyond the count already handled.
  const int fresh = outside - removed_;
  if (fresh <= 0) return "";
  if (first >= points.count) {  // none still moving: take the first outside
    Kokkos::parallel_reduce(
        "guard_first_outside", Kokkos::RangePolicy<ExecSpace>(0, points.count),
        KOKKOS_LAMBDA(const int p, int& lowest) {
          if (element(p) < 0 && p < lowest) lowest = p;
        },
        Kokkos::Min<int>(first));
  }
  std::ostringstream out;
  out << fresh << " material point(s) left the background mesh " << at(place) << ", first "
      << pointText(points, first);
  if (spec_.leaving_points == LeavingPoints::Stop)
    throw RunError(out.str() +
                   "; the run stops here (the last output is kept; Guards/Points Leaving "
                   "Mesh: remove would take such points out and go on, or enlarge the mesh)");
  Kokkos::parallel_for(
      "guard_remove_outside", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        if (element(p) >= 0) return;
        for (int d = 0; d < kDim; ++d) velocity_solid(p, d) = velocity_liquid(p, d) = 0;
        for (int c = 0; c < kAffineComponents; ++c) affine_solid(p, c) = affine_liquid(p, c) = 0;
      });
  removed_ = outside;
  out << "; removed from the computation (" << removed_ << " removed so far)";
  return out.str();
}

}  // namespace argine
