#include "argine/boundary/HydraulicConditions.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "argine/core/Error.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {

namespace {

bool isHydraulic(BoundaryKind kind) {
  return kind == BoundaryKind::TotalHead || kind == BoundaryKind::PressureSeries ||
         kind == BoundaryKind::Infiltration || kind == BoundaryKind::SeepageFace;
}

/// Copies `values` into `view`, reallocating only when the length changed (plan() runs
/// every step; the lists keep their length while the boundary does not change).
template <class T>
void toDevice(const std::vector<T>& values, const char* label, Kokkos::View<T*, MemSpace>& view) {
  if (view.extent(0) != values.size() || !view.data())
    view = Kokkos::View<T*, MemSpace>(std::string(label), values.size());
  auto host = Kokkos::create_mirror_view(view);
  for (std::size_t k = 0; k < values.size(); ++k) host(k) = values[k];
  Kokkos::deep_copy(view, host);
}

}  // namespace

TimeSeries makeTimeSeries(const TimeSeriesSpec& spec, Real stage_start) {
  const Real offset = spec.origin == TimeOrigin::StageStart ? stage_start : 0;
  switch (spec.source) {
    case TimeSeriesSpec::Source::Constant:
      return TimeSeries::constant(spec.value);
    case TimeSeriesSpec::Source::Table:
      return TimeSeries::fromPairs(spec.pairs, spec.where).shifted(offset);
    case TimeSeriesSpec::Source::File:
      return TimeSeries::fromCsvFile(spec.file, spec.where).shifted(offset);
  }
  return TimeSeries::constant(spec.value);
}

LinearInX makeLinearInX(const HydraulicSpec& spec, Real stage_start) {
  LinearInX profile;
  if (!spec.linear_in_x) return profile;
  profile.active = true;
  profile.x0 = spec.x_range[0];
  profile.x1 = spec.x_range[1];
  profile.end = makeTimeSeries(spec.end_series, stage_start);
  return profile;
}

HydraulicConditions::HydraulicConditions(const Mesh& mesh, const StageSpec& stage,
                                         Real stage_start) {
  for (const BoundarySpec& spec : stage.boundaries) {
    if (!isHydraulic(spec.kind)) continue;
    const std::string where = "Stages/" + stage.name + "/Boundary Conditions/" + spec.name;
    HydraulicCondition condition;
    condition.name = spec.name;
    condition.kind = spec.kind;
    condition.on_zone = spec.hydraulic.on_zone;
    if (condition.on_zone) {
      condition.zone = makeZone(spec.hydraulic.zone);
    } else {
      const SideSet* set = mesh.findSideSet(spec.side_set);
      if (!set) {
        std::string names;
        for (const auto& name : mesh.sideSetNames()) names += (names.empty() ? "" : ", ") + name;
        throw InputError(where, "side set '" + spec.side_set +
                                    "' is not in the mesh; the mesh has side sets: " +
                                    (names.empty() ? "(none)" : names));
      }
      for (std::size_t k = 0; k < set->elements.size(); ++k)
        condition.side_set.push_back({set->elements[k], set->sides[k]});
    }
    if (spec.kind != BoundaryKind::SeepageFace)
      condition.series = makeTimeSeries(spec.hydraulic.series, stage_start);
    condition.linear_in_x = makeLinearInX(spec.hydraulic, stage_start);
    condition.above = spec.hydraulic.above;
    condition.pressure_above = spec.hydraulic.pressure_above;
    condition.ponding = spec.hydraulic.ponding;
    condition.liquid_density = spec.hydraulic.liquid_density;
    conditions_.push_back(std::move(condition));
  }
  atmosphere_ = stage.atmosphere_on_free_surfaces;
  if (headThroughSoil(stage) >= 0) {  // checked: one total head, continuous at its level
    heads_through_soil_ = true;
    for (std::size_t c = 0; c < conditions_.size(); ++c)
      if (conditions_[c].kind == BoundaryKind::TotalHead) through_soil_head_ = c;
  }
  sides_used_.resize(conditions_.size());
  current_values_.assign(conditions_.size(), 0.0);
  current_end_values_.assign(conditions_.size(), 0.0);
}

namespace {

/// A condition's series value at `time` (0 for a seepage face, which has none) and its value
/// at x1 (the same value unless the pressure is linear in x).
std::array<Real, 2> valuesAt(const HydraulicCondition& condition, Real time) {
  const Real value = condition.kind == BoundaryKind::SeepageFace ? 0 : condition.series.at(time);
  return {value, condition.linear_in_x.active ? condition.linear_in_x.end.at(time) : value};
}

/// The nodal loads of `forces` (node -> liquid components, then mixture) into `loads`, in
/// increasing node order.
void toDevice(NodeTable<std::array<Real, 2 * kDim>>& forces, NodalLoads& loads) {
  const std::vector<int>& nodes = forces.sortedNodes();
  const std::size_t n = nodes.size();
  if (loads.count() != static_cast<int>(n)) {
    loads.node = Kokkos::View<int*, MemSpace>("hydraulic_load_node", n);
    loads.mixture = Kokkos::View<Real* [kDim], MemSpace>("hydraulic_load_mixture", n);
    loads.liquid = Kokkos::View<Real* [kDim], MemSpace>("hydraulic_load_liquid", n);
  }
  auto node = Kokkos::create_mirror_view(loads.node);
  auto mixture = Kokkos::create_mirror_view(loads.mixture);
  auto liquid = Kokkos::create_mirror_view(loads.liquid);
  for (std::size_t j = 0; j < n; ++j) {
    const int i = nodes[j];
    const std::array<Real, 2 * kDim>& f = forces.at(i);
    node(j) = i;
    for (int d = 0; d < kDim; ++d) {
      liquid(j, d) = f[d];
      mixture(j, d) = f[kDim + d];
    }
  }
  Kokkos::deep_copy(loads.node, node);
  Kokkos::deep_copy(loads.mixture, mixture);
  Kokkos::deep_copy(loads.liquid, liquid);
}

}  // namespace

HeadPressureField HydraulicConditions::headFieldThroughSoil(Real gravity) const {
  const HydraulicCondition& head = conditions_.at(through_soil_head_);
  HeadPressureField field;
  field.rho_g = head.liquid_density * gravity;
  field.head = current_values_.at(through_soil_head_);
  field.suction_above = head.above == AboveLevel::LinearSuction;
  return field;
}

Real HydraulicConditions::largestCurrentValue(std::size_t condition) const {
  return std::max(current_values_[condition], current_end_values_[condition]);
}

bool HydraulicConditions::valuesUnchangedAt(Real time) const {
  for (std::size_t c = 0; c < conditions_.size(); ++c) {
    const std::array<Real, 2> values = valuesAt(conditions_[c], time);
    if (values[0] != current_values_[c] || values[1] != current_end_values_[c]) return false;
  }
  return true;
}

void HydraulicConditions::sidesOf(const HydraulicCondition& condition, const FreeBoundary& boundary,
                                  std::vector<FreeSide>& sides) const {
  sides.clear();
  if (condition.on_zone) {
    for (const FreeSide& side : boundary.sides())
      if (zoneContains(condition.zone, side.midpoint(0), side.midpoint(1))) sides.push_back(side);
  } else {
    for (const auto& [element, local] : condition.side_set)
      if (boundary.isActive(element)) sides.push_back(boundary.sideOf(element, local));
  }
}

bool HydraulicConditions::sealsSide(const std::vector<unsigned char>& rules, const FreeSide& side) {
  if (rules.empty()) return false;
  for (const int node : {side.a, side.b})
    for (int d = 0; d < kDim; ++d)
      if (std::fabs(side.normal[d]) > 1e-9 && !(rules[node] & (d == 0 ? kLockedX : kLockedY)))
        return false;
  return true;
}

void HydraulicConditions::plan(Real time, Real gravity, const FreeBoundary& boundary) {
  using Claim = PlanScratch::Claim;
  PlanScratch& t = scratch_;  // every table emptied here, its storage kept
  t.forces.clear();
  t.head_forces.clear();
  t.corrections.clear();
  t.owner.clear();
  t.face.resize(conditions_.size() + 1);  // the atmosphere's last
  for (auto& face : t.face) face.clear();
  for (std::size_t c = 0; c < conditions_.size(); ++c) {
    const HydraulicCondition& condition = conditions_[c];
    const int index = static_cast<int>(c);
    std::vector<FreeSide>& sides = sides_used_[c];
    sidesOf(condition, boundary, sides);
    const std::array<Real, 2> values = valuesAt(condition, time);
    const Real value = values[0];
    current_values_[c] = value;
    current_end_values_[c] = values[1];
    auto claim = [&](int node, FluxCorrection kind, Real rain) {
      t.corrections.emplace(node, Claim{static_cast<int>(kind), rain, index});
    };
    for (const FreeSide& side : sides) {
      for (const int node : {side.a, side.b}) {
        t.owner.emplace(node, index);
        auto& sum = t.face[c][node];
        for (int d = 0; d < kDim; ++d) sum[d] += 0.5 * side.length * side.normal[d];
      }
      Real fa[kDim] = {0, 0}, fb[kDim] = {0, 0};  // liquid
      Real ma[kDim] = {0, 0}, mb[kDim] = {0, 0};  // mixture
      switch (condition.kind) {
        case BoundaryKind::TotalHead: {
          HeadPressureRule rule;
          rule.rho_g = condition.liquid_density * gravity;
          rule.head = value;
          rule.above = condition.above;
          rule.pressure_above = condition.pressure_above;
          headSideForces(side.xa, side.xb, side.length, side.normal, rule, fa, fb);
          rule.mixture = true;
          headSideForces(side.xa, side.xb, side.length, side.normal, rule, ma, mb);
          if (condition.above == AboveLevel::SeepageFace) {  // nodes above the level
            if (side.xa[1] > value) claim(side.a, FluxCorrection::SeepageFace, 0.0);
            if (side.xb[1] > value) claim(side.b, FluxCorrection::SeepageFace, 0.0);
          }
          break;
        }
        case BoundaryKind::PressureSeries: {
          // Linear along the side either way: uniform, or linear in x (LinearInX.hpp).
          const LinearInX& in_x = condition.linear_in_x;
          const Real pa = in_x.at(value, time, side.xa[0]), pb = in_x.at(value, time, side.xb[0]);
          pressureSideForces(pa, pb, side.length, side.normal, fa, fb);
          pressureSideForces(mixtureLoadPressure(pa), mixtureLoadPressure(pb), side.length,
                             side.normal, ma, mb);
          break;
        }
        case BoundaryKind::Infiltration: {
          const FluxCorrection kind = condition.ponding ? FluxCorrection::InfiltrationPonding
                                                        : FluxCorrection::Infiltration;
          for (const int node : {side.a, side.b}) claim(node, kind, value);
          break;
        }
        case BoundaryKind::SeepageFace:
          for (const int node : {side.a, side.b}) claim(node, FluxCorrection::SeepageFace, 0.0);
          break;
        default:
          break;
      }
      if (fa[0] != 0 || fa[1] != 0 || fb[0] != 0 || fb[1] != 0) {
        auto& to = heads_through_soil_ && condition.kind == BoundaryKind::TotalHead ? t.head_forces
                                                                                    : t.forces;
        for (int d = 0; d < kDim; ++d) {
          to[side.a][d] += fa[d];
          to[side.b][d] += fb[d];
          to[side.a][kDim + d] += ma[d];
          to[side.b][kDim + d] += mb[d];
        }
      }
    }
  }

  // The nodes the conditions correct (the atmosphere's, claimed below, are not among them).
  t.conditioned = t.corrections.nodes();  // sorted with the loaded nodes below

  // The atmosphere on the free sides no condition covers: seepage-face nodes where no
  // condition owns the node (a condition's node keeps its condition's rule).
  const int atmosphere = static_cast<int>(conditions_.size());
  if (atmosphere_) {
    t.covered.clear();
    for (const auto& sides : sides_used_)
      for (const FreeSide& side : sides) t.covered.emplace_back(side.element, side.side);
    std::sort(t.covered.begin(), t.covered.end());
    auto covered = [&](const FreeSide& side) {
      return std::binary_search(t.covered.begin(), t.covered.end(),
                                std::make_pair(side.element, side.side));
    };
    auto rule = [&](int node) { return rules_.empty() ? 0u : unsigned{rules_[node]}; };
    auto ruled = [&](const FreeSide& side) {  // sealed, or its p_L prescribed (setOtherLiquidRules)
      return (rule(side.a) & rule(side.b) & kPressurePrescribed) != 0 || sealsSide(rules_, side);
    };
    for (const FreeSide& side : boundary.sides()) {
      if (covered(side) || ruled(side)) continue;
      for (const int node : {side.a, side.b}) {
        if (t.owner.contains(node) || (rule(node) & kPressurePrescribed)) continue;
        t.corrections.emplace(
            node, Claim{static_cast<int>(FluxCorrection::SeepageFace), 0.0, atmosphere});
        auto& sum = t.face[atmosphere][node];
        for (int d = 0; d < kDim; ++d) sum[d] += 0.5 * side.length * side.normal[d];
      }
    }
  }

  // loads: liquid and mixture (the head's apart when it loads through the soil)
  toDevice(t.forces, loads_);
  toDevice(t.head_forces, head_loads_);

  t.node.clear();
  t.kind.clear();
  t.q_out.clear();
  t.normal.clear();
  t.length.clear();
  for (const int node : t.corrections.sortedNodes()) {
    const Claim& entry = t.corrections.at(node);
    t.node.push_back(node);
    t.kind.push_back(entry.kind);
    const auto& sum = t.face[entry.condition].at(node);
    const Real length = std::hypot(sum[0], sum[1]);
    Real normal[kDim];
    for (int d = 0; d < kDim; ++d) {
      normal[d] = length > 0 ? sum[d] / length : 0;
      t.normal.push_back(normal[d]);
    }
    t.q_out.push_back(verticalRainOutwardFlux(entry.rain, normal));
    t.length.push_back(length);
  }
  const std::size_t n = t.node.size();
  const bool resized = corrections_.count() != static_cast<int>(n);
  toDevice(t.node, "correction_node", corrections_.node);
  toDevice(t.kind, "correction_kind", corrections_.kind);
  toDevice(t.q_out, "correction_q_out", corrections_.q_out);
  toDevice(t.length, "correction_face_length", corrections_.face_length);
  if (resized || !corrections_.applied.data()) {
    corrections_.applied = Kokkos::View<int*, MemSpace>("correction_applied", n);
    corrections_.normal = Kokkos::View<Real* [kDim], MemSpace>("correction_normal", n);
  }
  {
    auto normal = Kokkos::create_mirror_view(corrections_.normal);
    for (std::size_t j = 0; j < n; ++j)
      for (int d = 0; d < kDim; ++d) normal(j, d) = t.normal[kDim * j + d];
    Kokkos::deep_copy(corrections_.normal, normal);
  }

  for (const int node : t.forces.nodes()) t.conditioned.push_back(node);
  for (const int node : t.head_forces.nodes()) t.conditioned.push_back(node);
  std::sort(t.conditioned.begin(), t.conditioned.end());
  t.conditioned.erase(std::unique(t.conditioned.begin(), t.conditioned.end()), t.conditioned.end());
  toDevice(t.conditioned, "conditioned_node", conditioned_nodes_);

  t.owned.clear();
  t.owners.clear();
  for (const int node : t.owner.sortedNodes()) {
    t.owned.push_back(node);
    t.owners.push_back(t.owner.at(node));
  }
  toDevice(t.owned, "owned_node", ownership_.node);
  toDevice(t.owners, "owner", ownership_.owner);
}

}  // namespace argine
