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
  criteria_ = spec.criteria;
  stale_ = true;
  calls_since_update_ = 0;
}

namespace {

/// The criteria's inputs of every point as arrays (CriterionGathered in the header), so that
/// each criterion is one loop over contiguous values without branches that GCC evaluates
/// for two points per instruction (SSE2; doc/scaling.md).
struct CriterionArrays {
  MaterialPoints points;
  Kokkos::View<Real* [kCriterionGathered], Kokkos::LayoutLeft, MemSpace> gathered_p;
  Real mass_scaling = 1;

  KOKKOS_INLINE_FUNCTION CriterionInput input(int p) const {
    CriterionInput in;
    in.element_size = gathered_p(p, kGatheredElementSize);
    in.porosity = points.porosity(p);
    in.solid_density = gathered_p(p, kGatheredSolidDensity);
    in.liquid_bulk_modulus = gathered_p(p, kGatheredBulkModulus);
    in.constrained_modulus = gathered_p(p, kGatheredConstrainedModulus);
    in.mass_scaling = mass_scaling;
    in.saturation = points.saturation(p);
    in.saturation_suction_derivative = gathered_p(p, kGatheredSaturationSlope);
    in.liquid_density = points.density_liquid(p);
    in.hydraulic_conductivity = points.conductivity(p);
    return in;
  }
};

/// step_pc(p, slot) = criterion kKind at every point (also where it does not apply: the
/// minimum skips those).
template <CriterionKind kKind>
void evaluateCriterion(const CriterionArrays& arrays, int slot, int count,
                       Kokkos::View<Real**, Kokkos::LayoutLeft, MemSpace> step_pc) {
  // An int index like the lambda's: with Kokkos' default (64-bit) index the narrowing to
  // int keeps GCC from vectorising the loop.
  Kokkos::parallel_for(
      "critical_time_step", Kokkos::RangePolicy<ExecSpace, Kokkos::IndexType<int>>(0, count),
      KOKKOS_LAMBDA(const int p) { step_pc(p, slot) = criticalStep(kKind, arrays.input(p)); });
}

void evaluateCriterion(CriterionKind kind, const CriterionArrays& arrays, int slot, int count,
                       Kokkos::View<Real**, Kokkos::LayoutLeft, MemSpace> step_pc) {
  switch (kind) {
#define ARGINE_CRITERION_CASE(K) \
  case CriterionKind::K:         \
    return evaluateCriterion<CriterionKind::K>(arrays, slot, count, step_pc);
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

}  // namespace

TimeStepChoice TimeStepControl::evaluate(const MaterialPoints& points,
                                         const MaterialTable& table) const {
  const auto materials_m = table.materials();
  const auto element_size = element_size_;
  const int count = static_cast<int>(criteria_.size());
  const int slots = count + 1;            // slot `count` = dry CFL of a dry point
  bool any_dry = false, any_wet = false;  // the passes no point takes are skipped
  for (int m = 0; m < table.count(); ++m) {
    any_dry = any_dry || !carriesLiquid(table.host(m).phase);
    any_wet = any_wet || carriesLiquid(table.host(m).phase);
  }
  if (static_cast<int>(gathered_p_.extent(0)) != points.count ||
      static_cast<int>(step_pc_.extent(1)) != slots) {
    gathered_p_ = Kokkos::View<Real* [kCriterionGathered], Kokkos::LayoutLeft, MemSpace>(
        "criterion_inputs_p", points.count);
    step_pc_ = Kokkos::View<Real**, Kokkos::LayoutLeft, MemSpace>("critical_steps_pc", points.count,
                                                                  slots);
  }
  const MaterialPoints pts = points;
  const auto gathered_p = gathered_p_;
  const auto step_pc = step_pc_;

  // The element size and the material's parameters of each point, so that the criteria's
  // loops need no branch; a point with element < 0 gets size 0 (it is skipped below).
  Kokkos::parallel_for(
      "critical_time_step_inputs", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        const int e = pts.element(p);
        const PointMaterial& material = materials_m(pts.material(p));
        gathered_p(p, kGatheredElementSize) = e < 0 ? Real(0) : element_size(e);
        gathered_p(p, kGatheredSolidDensity) = material.solid_density;
        gathered_p(p, kGatheredBulkModulus) = material.liquid.bulk_modulus;
        // precomputed per material: one division less
        gathered_p(p, kGatheredConstrainedModulus) = material.constrained_modulus;
        gathered_p(p, kGatheredSaturationSlope) =
            material.phase == PhaseModel::Unsaturated
                ? saturationSuctionDerivative(material.retention,
                                              suctionOfPressure(pts.pressure_liquid(p)))
                : 0;
      });
  const CriterionArrays arrays{points, gathered_p, mass_scaling_};
  for (int c = 0; c < count && any_wet; ++c)
    evaluateCriterion(criteria_[c], arrays, c, points.count, step_pc);
  // Dry points have no liquid: the dry CFL criterion (4.62) alone (the header).
  if (any_dry) evaluateCriterion(CriterionKind::CflDry, arrays, count, points.count, step_pc);

  // The minimum over the points in order and, per point, over its criteria in order (the
  // first of equal ones).
  using Reducer = Kokkos::MinLoc<Real, long>;
  Reducer::value_type best;
  Kokkos::parallel_reduce(
      "critical_time_step_minimum", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, Reducer::value_type& min) {
        if (pts.element(p) < 0) return;
        const bool wet = carriesLiquid(materials_m(pts.material(p)).phase);
        const int first = wet ? 0 : count, last = wet ? count : count + 1;
        for (int c = first; c < last; ++c) {
          const Real dt = step_pc(p, c);
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
    choice.governing = criteria_[slot];
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
