#include "argine/seepage/SeepageBoundary.hpp"

#include <cmath>
#include <map>
#include <set>

#include "argine/boundary/FreeBoundary.hpp"
#include "argine/boundary/HydraulicConditions.hpp"
#include "argine/boundary/Zone.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"

namespace argine {

void SeepageBoundaryConditions::addPressures(const std::vector<int>& nodes,
                                             const std::vector<Real>& values) {
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    bool found = false;
    for (std::size_t k = 0; k < pressure_nodes.size(); ++k)
      if (pressure_nodes[k] == nodes[j]) {
        pressures[k] = values[j];
        found = true;
      }
    if (!found) {
      pressure_nodes.push_back(nodes[j]);
      pressures.push_back(values[j]);
    }
  }
}

void SeepageBoundaryConditions::addSupplies(const std::vector<int>& nodes,
                                            const std::vector<Real>& rates, bool switchable_nodes) {
  for (std::size_t j = 0; j < nodes.size(); ++j) {
    bool found = false;
    for (std::size_t k = 0; k < supply_nodes.size(); ++k)
      if (supply_nodes[k] == nodes[j]) {
        supplies[k] += rates[j];
        switchable[k] = switchable[k] || switchable_nodes;
        found = true;
      }
    if (!found) {
      supply_nodes.push_back(nodes[j]);
      supplies.push_back(rates[j]);
      switchable.push_back(switchable_nodes ? 1 : 0);
    }
  }
}

SideSetNodes sideSetNodeLengths(const Mesh& mesh, const SideSet& set) {
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  const auto C = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.connectivity);
  const int per = mesh.nodesPerElement();
  std::map<int, Real> length_of;
  for (std::size_t s = 0; s < set.elements.size(); ++s) {
    const int e = set.elements[s], side = set.sides[s];
    const int a = C(e, side), b = C(e, (side + 1) % per);
    const Real length = std::hypot(X(b, 0) - X(a, 0), X(b, 1) - X(a, 1));
    length_of[a] += 0.5 * length;
    length_of[b] += 0.5 * length;
  }
  SideSetNodes result;
  for (const auto& [node, length] : length_of) {
    result.nodes.push_back(node);
    result.lengths.push_back(length);
  }
  return result;
}

namespace {

/// Adds each side's L/2 to both end nodes.
void addSideLengths(const FreeSide& side, std::map<int, Real>& length_of) {
  length_of[side.a] += 0.5 * side.length;
  length_of[side.b] += 0.5 * side.length;
}

}  // namespace

SeepageBoundaryConditions SeepageBoundaryPlan::at(Real t_start, Real t_end, Real theta) const {
  SeepageBoundaryConditions out;
  for (const SeepageCondition& c : conditions) {
    const std::size_t count = c.nodes.size();
    switch (c.kind) {
      case BoundaryKind::LiquidPressure:
      case BoundaryKind::PressureSeries: {
        const Real value = c.series.at(t_end);
        std::vector<Real> values(count, value);
        for (std::size_t j = 0; j < count; ++j)
          values[j] = c.linear_in_x.at(value, t_end, c.abscissas[j]);
        out.addPressures(c.nodes, values);
        break;
      }
      case BoundaryKind::TotalHead: {
        // (4.50) with h_g = y: p_L = rho_L g (H - y) below the level.
        const Real head = c.series.at(t_end), rho_g = c.liquid_density * gravity;
        std::vector<int> fixed_nodes, face_nodes;
        std::vector<Real> fixed_values;
        for (std::size_t j = 0; j < count; ++j) {
          const Real y = c.heights[j];
          if (y <= head || c.above == AboveLevel::LinearSuction) {
            fixed_nodes.push_back(c.nodes[j]);
            fixed_values.push_back(rho_g * (head - y));
          } else if (c.above == AboveLevel::ConstantPressure) {
            fixed_nodes.push_back(c.nodes[j]);
            fixed_values.push_back(c.pressure_above);
          } else {
            face_nodes.push_back(c.nodes[j]);
          }
        }
        out.addPressures(fixed_nodes, fixed_values);
        out.addSupplies(face_nodes, std::vector<Real>(face_nodes.size(), 0.0), true);
        break;
      }
      case BoundaryKind::Infiltration: {
        const Real q = theta * c.series.at(t_end) + (1 - theta) * c.series.at(t_start);
        std::vector<Real> rates;
        for (const Real length : c.lengths) rates.push_back(q * length);
        out.addSupplies(c.nodes, rates, !c.ponding);
        break;
      }
      case BoundaryKind::SeepageFace:
        out.addSupplies(c.nodes, std::vector<Real>(count, 0.0), true);
        break;
      default:
        break;
    }
  }
  return out;
}

bool SeepageBoundaryPlan::timeDependent() const {
  for (const SeepageCondition& c : conditions)
    if (!c.series.isConstant() || (c.linear_in_x.active && !c.linear_in_x.end.isConstant()))
      return true;
  return false;
}

SeepageBoundaryPlan seepageBoundaryPlan(const Mesh& mesh, const MaterialPoints& points,
                                        const StageSpec& stage, Real stage_start) {
  SeepageBoundaryPlan plan;
  plan.gravity = stage.gravity;
  FreeBoundary boundary(mesh);
  boundary.detect(points);
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  std::set<int> claimed;  // a node belongs to the first condition in deck order
  for (const BoundarySpec& spec : stage.boundaries) {
    const bool pressure = spec.kind == BoundaryKind::LiquidPressure;
    const bool hydraulic =
        spec.kind == BoundaryKind::TotalHead || spec.kind == BoundaryKind::PressureSeries ||
        spec.kind == BoundaryKind::Infiltration || spec.kind == BoundaryKind::SeepageFace;
    if (!pressure && !hydraulic) continue;  // impermeable: natural; solid: fixed skeleton
    const std::string where = "Stages/" + stage.name + "/Boundary Conditions/" + spec.name;
    std::map<int, Real> length_of;
    if (hydraulic && spec.hydraulic.on_zone) {
      const Zone zone = makeZone(spec.hydraulic.zone);
      for (const FreeSide& side : boundary.sides())
        if (zoneContains(zone, side.midpoint(0), side.midpoint(1))) addSideLengths(side, length_of);
    } else {
      const SideSet* set = mesh.findSideSet(spec.side_set);
      if (!set)
        throw InputError(where + "/Side Set", "no side set '" + spec.side_set + "' in the mesh");
      for (std::size_t k = 0; k < set->elements.size(); ++k)
        if (boundary.isActive(set->elements[k]))
          addSideLengths(boundary.sideOf(set->elements[k], set->sides[k]), length_of);
    }
    SeepageCondition condition;
    condition.name = spec.name;
    condition.kind = spec.kind;
    for (const auto& [node, length] : length_of) {
      if (!claimed.insert(node).second) continue;
      condition.nodes.push_back(node);
      condition.lengths.push_back(length);
      condition.abscissas.push_back(X(node, 0));
      condition.heights.push_back(X(node, 1));
    }
    if (pressure) {
      condition.series = TimeSeries::constant(spec.pressure);
    } else {
      if (spec.kind != BoundaryKind::SeepageFace)
        condition.series = makeTimeSeries(spec.hydraulic.series, stage_start);
      condition.linear_in_x = makeLinearInX(spec.hydraulic, stage_start);
      condition.above = spec.hydraulic.above;
      condition.pressure_above = spec.hydraulic.pressure_above;
      condition.ponding = spec.hydraulic.ponding;
      condition.liquid_density = spec.hydraulic.liquid_density;
    }
    plan.conditions.push_back(std::move(condition));
  }
  return plan;
}

}  // namespace argine
