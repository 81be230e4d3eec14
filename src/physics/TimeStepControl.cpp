#include "argine/physics/TimeStepControl.hpp"

#include <limits>
#include <sstream>

#include "argine/core/Error.hpp"
#include "argine/input/Deck.hpp"
#include "argine/mesh/MeshGeometry.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/timestep/Criteria.hpp"

namespace argine {

TimeStepControl::TimeStepControl(const Mesh& mesh)
    : element_size_(elementCharacteristicSizes(mesh)) {}

void TimeStepControl::configure(const TimeStepSpec& spec, Real mass_scaling,
                                const std::string& stage) {
  const std::string where = "Stages/" + stage + "/Time Step";
  automatic_ = spec.automatic;
  fixed_step_ = spec.fixed_step;
  safety_factor_ = spec.safety_factor;
  mass_scaling_ = mass_scaling;
  update_interval_ = spec.update_interval > 0 ? spec.update_interval : 1;
  if (!automatic_ && !(fixed_step_ > 0)) {
    std::ostringstream out;
    out << "expected a positive fixed step (s), got " << fixed_step_;
    throw InputError(where + "/Fixed Step", out.str());
  }
  if (automatic_ && !(safety_factor_ > 0)) {
    std::ostringstream out;
    out << "expected a positive safety factor, got " << safety_factor_;
    throw InputError(where + "/Safety Factor", out.str());
  }
  if (automatic_ && spec.criteria.empty())
    throw InputError(where + "/Criteria", "expected at least one criterion, got none");
  criteria_ = Kokkos::View<CriterionKind*, MemSpace>("criteria", spec.criteria.size());
  auto host = Kokkos::create_mirror_view(criteria_);
  for (std::size_t c = 0; c < spec.criteria.size(); ++c) host(c) = spec.criteria[c];
  Kokkos::deep_copy(criteria_, host);
  stale_ = true;
  calls_since_update_ = 0;
}

TimeStepChoice TimeStepControl::evaluate(const MaterialPoints& points,
                                         const MaterialTable& table) const {
  const auto materials_m = table.materials();
  const auto criteria = criteria_;
  const auto element_size = element_size_;
  const int count = static_cast<int>(criteria.extent(0));
  const int slots = count + 1;  // slot `count` = dry CFL of a dry point
  const Real mass_scaling = mass_scaling_;
  const MaterialPoints pts = points;

  using Reducer = Kokkos::MinLoc<Real, long>;
  Reducer::value_type best;
  Kokkos::parallel_reduce(
      "critical_time_step", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, Reducer::value_type& min) {
        const int e = pts.element(p);
        if (e < 0) return;
        const PointMaterial& material = materials_m(pts.material(p));
        CriterionInput in;
        in.element_size = element_size(e);
        in.porosity = pts.porosity(p);
        in.solid_density = material.solid_density;
        in.liquid_bulk_modulus = material.liquid.bulk_modulus;
        in.constrained_modulus = material.constrained_modulus;  // precomputed: one division less
        in.mass_scaling = mass_scaling;
        if (!carriesLiquid(material.phase)) {
          const Real dt = criticalStepCflDry(in);
          if (dt < min.val) {
            min.val = dt;
            min.loc = static_cast<long>(p) * slots + count;
          }
          return;
        }
        in.saturation = pts.saturation(p);
        in.saturation_suction_derivative =
            material.phase == PhaseModel::Unsaturated
                ? saturationSuctionDerivative(material.retention,
                                              suctionOfPressure(pts.pressure_liquid(p)))
                : 0;
        in.liquid_density = pts.density_liquid(p);
        in.hydraulic_conductivity = pts.conductivity(p);
        for (int c = 0; c < count; ++c) {
          const Real dt = criticalStep(criteria(c), in);
          if (dt < min.val) {
            min.val = dt;
            min.loc = static_cast<long>(p) * slots + c;
          }
        }
      },
      Reducer(best));

  TimeStepChoice choice;
  choice.automatic = true;
  // No limiting point leaves the reducer's identity (the largest Real) in place.
  const bool limited = best.val < std::numeric_limits<Real>::max() && best.loc >= 0;
  choice.critical_step = limited ? best.val : kmath::infinity();
  if (!limited) return choice;
  const int point = static_cast<int>(best.loc / slots);
  const int slot = static_cast<int>(best.loc % slots);
  if (slot == count) {
    choice.governing = CriterionKind::CflDry;
  } else {
    auto host = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), criteria);
    choice.governing = host(slot);
  }
  choice.point = point;
  auto id = Kokkos::create_mirror_view_and_copy(
      Kokkos::HostSpace(), Kokkos::subview(points.id, std::make_pair(point, point + 1)));
  auto position = Kokkos::create_mirror_view_and_copy(
      Kokkos::HostSpace(),
      Kokkos::subview(points.position, std::make_pair(point, point + 1), Kokkos::ALL));
  choice.point_id = id(0);
  choice.position[0] = position(0, 0);
  choice.position[1] = position(0, 1);
  return choice;
}

void TimeStepControl::pointsReordered(const MaterialPoints& points) {
  if (choice_.point < 0) return;
  const int id = choice_.point_id;
  const auto id_p = points.id;
  int index = -1;
  Kokkos::parallel_reduce(
      "find_point_by_id", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, int& found) {
        if (id_p(p) == id && p > found) found = p;
      },
      Kokkos::Max<int>(index));
  choice_.point = index;
}

const TimeStepChoice& TimeStepControl::next(const MaterialPoints& points,
                                            const MaterialTable& table) {
  if (!automatic_) {
    choice_ = TimeStepChoice{};
    choice_.time_step = fixed_step_;
    return choice_;
  }
  if (stale_ || calls_since_update_ >= update_interval_) {
    choice_ = evaluate(points, table);
    if (!(choice_.critical_step < kmath::infinity()))
      throw RunError(
          "no critical time-step criterion limits the step (no located points, or "
          "the criteria do not apply to any point); use a fixed step");
    if (!(choice_.critical_step > 0)) {
      std::ostringstream out;
      out << "the critical time step is " << choice_.critical_step << " s ("
          << criterionName(choice_.governing) << " criterion) at point " << choice_.point_id
          << " (index " << choice_.point << ") at (" << choice_.position[0] << ", "
          << choice_.position[1] << "): the run cannot advance (e.g. zero conductivity)";
      throw RunError(out.str());
    }
    choice_.time_step = safety_factor_ * choice_.critical_step;
    stale_ = false;
    calls_since_update_ = 0;
  }
  ++calls_since_update_;
  return choice_;
}

}  // namespace argine
