#include "argine/physics/TimeStepControl.hpp"

#include <limits>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "argine/core/Error.hpp"
#include "argine/core/UntrackedViews.hpp"
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
                                const std::string& stage, bool implicit_drag) {
  const std::string where = "Stages/" + stage + "/Time Step";
  automatic_ = spec.automatic;
  fixed_step_ = spec.fixed_step;
  safety_factor_ = spec.safety_factor;
  mass_scaling_ = mass_scaling;
  implicit_drag_ = implicit_drag;
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
  criteria_ = spec.criteria;
  stale_ = true;
  calls_since_update_ = 0;
}

namespace {

/// The criteria's inputs of every point as arrays (CriterionGathered in the header), so that
/// each criterion is one loop over contiguous values without branches that GCC evaluates
/// for several points per instruction (doc/scaling.md).
/// Only the point fields the criteria read: every kernel copies its lambda's captures, and a
/// copied View counts a reference (all 28 of MaterialPoints' were several per cent of the
/// shipped levee's step).
struct CriterionArrays {
  Kokkos::View<const Real*, MemSpace> porosity_p, saturation_p, density_liquid_p, conductivity_p;
  Kokkos::View<Real* [kCriterionGathered], Kokkos::LayoutLeft, MemSpace> gathered_p;
  Real mass_scaling = 1;
  bool implicit_drag = false;

  CriterionArrays(const MaterialPoints& points,
                  Kokkos::View<Real* [kCriterionGathered], Kokkos::LayoutLeft, MemSpace> gathered,
                  Real scaling, bool drag)
      : porosity_p(points.porosity),
        saturation_p(points.saturation),
        density_liquid_p(points.density_liquid),
        conductivity_p(points.conductivity),
        gathered_p(gathered),
        mass_scaling(scaling),
        implicit_drag(drag) {}

  KOKKOS_INLINE_FUNCTION CriterionInput input(int p) const {
    CriterionInput in;
    in.element_size = gathered_p(p, kGatheredElementSize);
    in.porosity = porosity_p(p);
    in.solid_density = gathered_p(p, kGatheredSolidDensity);
    in.liquid_bulk_modulus = gathered_p(p, kGatheredBulkModulus);
    in.constrained_modulus = gathered_p(p, kGatheredConstrainedModulus);
    in.mass_scaling = mass_scaling;
    in.implicit_drag = implicit_drag;
    in.saturation = saturation_p(p);
    in.saturation_suction_derivative = gathered_p(p, kGatheredSaturationSlope);
    in.liquid_density = density_liquid_p(p);
    in.hydraulic_conductivity = conductivity_p(p);
    return in;
  }
};

/// kGatheredHeldTo values: which criteria hold a point.
constexpr Real kHeldToNone = 0;     ///< outside the mesh: none
constexpr Real kHeldToLiquid = 1;   ///< liquid-carrying: the stage's criteria
constexpr Real kHeldToDryCfl = -1;  ///< dry: the dry CFL criterion (the header)

/// No limiting criterion leaves this (the identity of Kokkos' MinLoc) in place.
constexpr Real kUnlimited = std::numeric_limits<Real>::max();

/// limit_p(p) = min(limit_p(p), criterion kKind at p) where limit_p(p) is not NaN: a point
/// the stage's criteria do not hold starts from NaN (critical_time_step_inputs), which no
/// step is smaller than. One array written, so that GCC's run-time alias checks stay within
/// its limit and the loop is vectorised.
template <CriterionKind kKind>
void lowerLimitByCriterion(const CriterionArrays& arrays, int count,
                           Kokkos::View<Real*, MemSpace> limit_p) {
  // An int index like the lambda's: with Kokkos' default (64-bit) index the narrowing to
  // int keeps GCC from vectorising the loop.
  Kokkos::parallel_for(
      "critical_time_step", Kokkos::RangePolicy<ExecSpace, Kokkos::IndexType<int>>(0, count),
      KOKKOS_LAMBDA(const int p) {
        const Real dt = criticalStep(kKind, arrays.input(p));
        const Real limit = limit_p(p);
        limit_p(p) = dt < limit ? dt : limit;
      });
}

void lowerLimitByCriterion(CriterionKind kind, const CriterionArrays& arrays, int count,
                           Kokkos::View<Real*, MemSpace> limit_p) {
  switch (kind) {
#define ARGINE_CRITERION_CASE(K) \
  case CriterionKind::K:         \
    return lowerLimitByCriterion<CriterionKind::K>(arrays, count, limit_p);
    ARGINE_CRITERION_CASE(CflDry)
    ARGINE_CRITERION_CASE(CflUndrained)
    ARGINE_CRITERION_CASE(Consolidation)
    ARGINE_CRITERION_CASE(Infiltration)
    ARGINE_CRITERION_CASE(UnsaturatedLiquid)
    ARGINE_CRITERION_CASE(UnsaturatedMixture)
    ARGINE_CRITERION_CASE(UnsaturatedCoupled)
    ARGINE_CRITERION_CASE(Mieremet)
    ARGINE_CRITERION_CASE(MieremetLiquidDrag)
#undef ARGINE_CRITERION_CASE
  }
}

/// limit_p(p) = the dry CFL criterion (4.62) at every dry point (the header); the others keep
/// theirs.
void limitDryPoints(const CriterionArrays& arrays, int count,
                    Kokkos::View<Real*, MemSpace> limit_p) {
  Kokkos::parallel_for(
      "critical_time_step_dry", Kokkos::RangePolicy<ExecSpace, Kokkos::IndexType<int>>(0, count),
      KOKKOS_LAMBDA(const int p) {
        const Real dt = criticalStep(CriterionKind::CflDry, arrays.input(p));
        const bool dry = arrays.gathered_p(p, kGatheredHeldTo) == kHeldToDryCfl;
        limit_p(p) = dry && dt < kUnlimited ? dt : limit_p(p);
      });
}

/// Criterion `kind` at point `point` alone (the same function as the passes, so the same
/// bits).
Real criticalStepAt(CriterionKind kind, const CriterionArrays& arrays, int point) {
  Real dt = 0;
  Kokkos::parallel_reduce(
      "critical_time_step_at", Kokkos::RangePolicy<ExecSpace>(point, point + 1),
      KOKKOS_LAMBDA(const int p, Real& out) { out = criticalStep(kind, arrays.input(p)); }, dt);
  return dt;
}

/// The criterion that gave point `point` its step `limit`: the dry CFL criterion at a dry
/// point, else the first of the stage's criteria, in their order, whose step there equals
/// it (as the passes keep the first of equal steps: only a strictly smaller one replaces a
/// limit).
CriterionKind governingCriterion(const std::vector<CriterionKind>& criteria,
                                 const CriterionArrays& arrays, int point, Real limit) {
  Real held_to = kHeldToNone;
  Kokkos::deep_copy(held_to, Kokkos::subview(arrays.gathered_p, point, int(kGatheredHeldTo)));
  if (held_to == kHeldToDryCfl) return CriterionKind::CflDry;
  for (const CriterionKind kind : criteria)
    if (criticalStepAt(kind, arrays, point) == limit) return kind;
  throw std::logic_error("TimeStepControl: no criterion gives the point's critical step");
}

}  // namespace

TimeStepChoice TimeStepControl::evaluate(const MaterialPoints& points,
                                         const MaterialTable& table) const {
  const auto materials_m = untracked(table.materials());
  const auto element_size = untracked(element_size_);
  bool any_dry = false, any_wet = false;  // the passes no point takes are skipped
  for (int m = 0; m < table.count(); ++m) {
    any_dry = any_dry || !carriesLiquid(table.host(m).phase);
    any_wet = any_wet || carriesLiquid(table.host(m).phase);
  }
  // the SWRC slope only where a criterion of the stage reads it (0 is never read otherwise)
  bool slope_read = false;
  for (const CriterionKind kind : criteria_) slope_read = slope_read || readsSaturationSlope(kind);
  if (static_cast<int>(gathered_p_.extent(0)) != points.count) {
    gathered_p_ = Kokkos::View<Real* [kCriterionGathered], Kokkos::LayoutLeft, MemSpace>(
        "criterion_inputs_p", points.count);
    limit_p_ = Kokkos::View<Real*, MemSpace>("critical_step_p", points.count);
  }
  // the three point fields the kernel reads (as CriterionArrays: no copy of all 28)
  const auto element_p = untracked(points.element);
  const auto material_p = untracked(points.material);
  const auto pressure_liquid_p = untracked(points.pressure_liquid);
  const auto gathered_p = untracked(gathered_p_);
  const auto limit_p = untracked(limit_p_);

  // The element size and the material's parameters of each point, so that the criteria's
  // loops need no branch; which criteria hold it, and where its step starts from.
  Kokkos::parallel_for(
      "critical_time_step_inputs", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        const int e = element_p(p);
        const PointMaterial& material = materials_m(material_p(p));
        gathered_p(p, kGatheredElementSize) = e < 0 ? Real(0) : element_size(e);
        gathered_p(p, kGatheredSolidDensity) = material.solid_density;
        gathered_p(p, kGatheredBulkModulus) = material.liquid.bulk_modulus;
        // precomputed per material: one division less
        gathered_p(p, kGatheredConstrainedModulus) = material.constrained_modulus;
        gathered_p(p, kGatheredSaturationSlope) =
            slope_read && material.phase == PhaseModel::Unsaturated
                ? saturationSuctionDerivativeAtPressure(material.retention, pressure_liquid_p(p))
                : 0;
        const Real held_to = e < 0                           ? kHeldToNone
                             : carriesLiquid(material.phase) ? kHeldToLiquid
                                                             : kHeldToDryCfl;
        gathered_p(p, kGatheredHeldTo) = held_to;
        limit_p(p) = held_to == kHeldToLiquid ? kUnlimited : kmath::quietNaN();
      });
  const CriterionArrays arrays =
      untracked(CriterionArrays(points, gathered_p, mass_scaling_, implicit_drag_));
  if (any_wet)
    for (const CriterionKind kind : criteria_)
      lowerLimitByCriterion(kind, arrays, points.count, limit_p);
  if (any_dry) limitDryPoints(arrays, points.count, limit_p);

  // The minimum over the points in order (the first of equal ones; NaN is never smaller).
  using Reducer = Kokkos::MinLoc<Real, int>;
  Reducer::value_type best;
  Kokkos::parallel_reduce(
      "critical_time_step_minimum", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, Reducer::value_type& min) {
        if (limit_p(p) < min.val) {
          min.val = limit_p(p);
          min.loc = p;
        }
      },
      Reducer(best));

  TimeStepChoice choice;
  choice.automatic = true;
  const bool limited = best.val < kUnlimited && best.loc >= 0;
  choice.critical_step = limited ? best.val : kmath::infinity();
  if (!limited) return choice;
  const int point = best.loc;
  choice.governing = governingCriterion(criteria_, arrays, point, best.val);
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

int pointIndexOfId(const MaterialPoints& points, int id) {
  const auto id_p = points.id;
  int index = -1;
  Kokkos::parallel_reduce(
      "find_point_by_id", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, int& found) {
        if (id_p(p) == id && p > found) found = p;
      },
      Kokkos::Max<int>(index));
  return index >= 0 ? index : -1;  // (the reducer starts from the lowest int, not -1)
}

void TimeStepControl::pointsReordered(const MaterialPoints& points) {
  if (choice_.point < 0) return;
  choice_.point = pointIndexOfId(points, choice_.point_id);
}

template <class Evaluate>
const TimeStepChoice& TimeStepControl::advance(Evaluate&& evaluate) {
  if (!automatic_) {
    choice_ = TimeStepChoice{};
    choice_.time_step = fixed_step_;
    return choice_;
  }
  if (stale_ || calls_since_update_ >= update_interval_) {
    choice_ = evaluate();
    stale_ = false;
    calls_since_update_ = 0;
  }
  ++calls_since_update_;
  return choice_;
}

const TimeStepChoice& TimeStepControl::nextWithoutPoints() {
  return advance([] {
    TimeStepChoice none;
    none.automatic = true;
    none.time_step = none.critical_step = kmath::infinity();
    return none;
  });
}

const TimeStepChoice& TimeStepControl::next(const MaterialPoints& points,
                                            const MaterialTable& table) {
  return advance([&] {
    TimeStepChoice choice = evaluate(points, table);
    if (!(choice.critical_step < kmath::infinity()))
      throw RunError(
          "no critical time-step criterion limits the step (no located points, or "
          "the criteria do not apply to any point); use a fixed step");
    if (!(choice.critical_step > 0)) {
      std::ostringstream out;
      out << "the critical time step is " << choice.critical_step << " s ("
          << criterionName(choice.governing) << " criterion) at point " << choice.point_id
          << " (index " << choice.point << ") at (" << choice.position[0] << ", "
          << choice.position[1] << "): the run cannot advance (e.g. zero conductivity)";
      throw RunError(out.str());
    }
    choice.time_step = safety_factor_ * choice.critical_step;
    return choice;
  });
}

}  // namespace argine
