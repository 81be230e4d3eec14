#include "argine/init/K0Procedure.hpp"

#include <algorithm>
#include <cmath>

#include "argine/init/K0Formulas.hpp"
#include "argine/input/Deck.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

namespace {

/// Longest piece of an unsaturated layer integrated by one 4-point Gauss-Legendre rule (m):
/// S_L(p_L(z)) is smooth between the phreatic surface and the suction cap, and 4 points are
/// exact for cubics, so 0.1 m pieces keep the quadrature error far below 1e-6 of gamma.
constexpr Real kQuadraturePiece = 0.1;

constexpr Real kGaussNodes[4] = {-0.8611363115940526, -0.3399810435848563, 0.3399810435848563,
                                 0.8611363115940526};
constexpr Real kGaussWeights[4] = {0.3478548451374538, 0.6521451548625461, 0.6521451548625461,
                                   0.3478548451374538};

}  // namespace

K0Profile::K0Profile(const InitialisationSpec& spec, const Mesh& mesh,
                     const std::vector<MaterialSpec>& materials, Real gravity)
    : materials_(materials),
      table_(materials),
      ground_(spec.ground_surface, "Initialisation/Ground Surface (m)"),
      max_suction_(spec.max_suction),
      gravity_(gravity),
      columns_(mesh, elementMaterials(mesh, materials), regionMaterials(mesh, materials)) {
  if (!spec.phreatic_surface.empty())
    phreatic_ = Polyline(spec.phreatic_surface, "Initialisation/Phreatic Surface (m)");
}

Real K0Profile::liquidPressure(int material, Real x, Real y) const {
  const MaterialSpec& spec = materials_[material];
  if (spec.phase == PhaseModel::Dry) return 0;
  if (phreatic_.empty()) return spec.initial.liquid_pressure;
  return hydrostaticPressure(spec.liquid.density, gravity_, phreatic_.at(x), y, max_suction_);
}

Real K0Profile::saturation(int material, Real pressure) const {
  const PointMaterial& point_material = table_.host(material);
  if (!carriesLiquid(point_material.phase)) return 0;
  return saturationAndConductivity(point_material, pressure).saturation;
}

Real K0Profile::unitWeight(int material, Real x, Real y) const {
  const MaterialSpec& spec = materials_[material];
  const Real s = saturation(material, liquidPressure(material, x, y));
  return argine::unitWeight(spec.porosity, spec.solid_density, s, spec.liquid.density, gravity_);
}

Real K0Profile::layerWeight(int material, Real x, Real a, Real b) const {
  const MaterialSpec& spec = materials_[material];
  const bool varies = spec.phase == PhaseModel::Unsaturated && !phreatic_.empty();
  if (!varies) return unitWeight(material, x, 0.5 * (a + b)) * (b - a);
  // S_L varies only between the phreatic surface and the height where the cap is reached;
  // split there (the kinks of p_L(z)) and integrate the pieces by Gauss-Legendre.
  std::vector<Real> cuts{a, b};
  const Real y_ph = phreatic_.at(x);
  cuts.push_back(y_ph);
  if (max_suction_ >= 0) cuts.push_back(y_ph + max_suction_ / (spec.liquid.density * gravity_));
  std::sort(cuts.begin(), cuts.end());
  Real sum = 0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const Real lo = std::max(cuts[i], a), hi = std::min(cuts[i + 1], b);
    if (!(hi > lo)) continue;
    const int pieces = std::max(1, static_cast<int>(std::ceil((hi - lo) / kQuadraturePiece)));
    const Real h = (hi - lo) / pieces;
    for (int k = 0; k < pieces; ++k) {
      const Real mid = lo + (k + 0.5) * h;
      for (int g = 0; g < 4; ++g)
        sum += 0.5 * h * kGaussWeights[g] * unitWeight(material, x, mid + 0.5 * h * kGaussNodes[g]);
    }
  }
  return sum;
}

Real K0Profile::totalVerticalStress(Real x, Real y) const {
  const Real y_ground = ground_.at(x);
  Real weight = 0;
  for (const ColumnInterval& layer : columns_.intervals(x, y, y_ground))
    weight += layerWeight(layer.material, x, layer.y_low, layer.y_high);
  if (!phreatic_.empty()) {
    // Free water above the ground (a river, Fig. 4.6): its weight loads the ground surface.
    // Its density: water of the first liquid-carrying material (all water in practice).
    Real density = LiquidSpec{}.density;
    for (const auto& m : materials_)
      if (m.phase != PhaseModel::Dry) {
        density = m.liquid.density;
        break;
      }
    const Real depth = phreatic_.at(x) - std::max(y_ground, y);
    if (depth > 0) weight += density * gravity_ * depth;
  }
  return -weight;
}

K0State K0Profile::state(int material, Real x, Real y) const {
  K0State s;
  s.liquid_pressure = liquidPressure(material, x, y);
  s.saturation = saturation(material, s.liquid_pressure);
  s.total_vertical_stress = totalVerticalStress(x, y);
  s.effective_vertical_stress =
      bishopEffectiveStress(s.total_vertical_stress, s.saturation, s.liquid_pressure);
  s.earth_pressure_coefficient = materials_[material].initial.earth_pressure_coefficient;
  return s;
}

void applyK0Procedure(const K0Profile& profile, MaterialPoints& points) {
  // Host-side: once per run, and the column integrals are not kernel work.
  auto material = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.material);
  auto position = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.position);
  std::vector<K0State> states(points.count);
  for (int p = 0; p < points.count; ++p)
    states[p] = profile.state(material(p), position(p, 0), position(p, 1));

  Kokkos::View<Real* [2], Kokkos::HostSpace> host("k0_state", points.count);
  std::vector<Real> pressure(points.count);
  for (int p = 0; p < points.count; ++p) {
    pressure[p] = states[p].liquid_pressure;
    host(p, 0) = states[p].effective_vertical_stress;
    host(p, 1) = states[p].earth_pressure_coefficient;
  }
  auto state_m = Kokkos::create_mirror_view_and_copy(MemSpace(), host);
  const MaterialPoints pts = points;
  Kokkos::parallel_for(
      "apply_k0_procedure", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        const Real vertical = state_m(p, 0), k0 = state_m(p, 1);
        pts.stress_effective(p, XX) = k0 * vertical;
        pts.stress_effective(p, YY) = vertical;
        pts.stress_effective(p, ZZ) = k0 * vertical;
        pts.stress_effective(p, XY) = 0;
      });
  setPointLiquidPressures(profile.table(), pressure, points);
}

void setPointLiquidPressures(const MaterialTable& table, const std::vector<Real>& pressure,
                             MaterialPoints& points) {
  Kokkos::View<Real*, Kokkos::HostSpace> host("liquid_pressure", points.count);
  for (int p = 0; p < points.count; ++p) host(p) = pressure[p];
  auto pressure_m = Kokkos::create_mirror_view_and_copy(MemSpace(), host);
  const auto materials_m = table.materials();
  const MaterialPoints pts = points;
  Kokkos::parallel_for(
      "set_point_liquid_pressures", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        const PointMaterial& m = materials_m(pts.material(p));
        if (!carriesLiquid(m.phase)) return;
        const Real pressure = pressure_m(p);
        const Real density = liquidDensity(m.liquid, pressure);  // 4.13
        const LiquidState liquid = saturationAndConductivity(m, pressure);
        pts.pressure_liquid(p) = pressure;
        pts.density_liquid(p) = density;
        pts.saturation(p) = liquid.saturation;
        pts.conductivity(p) = liquid.conductivity;
        pts.mass_liquid(p) = pts.porosity(p) * liquid.saturation * density * pts.volume(p);  // 4.47
      });
}

std::string applyPorePressure(const InitialisationSpec& spec,
                              const std::vector<MaterialSpec>& materials, Real gravity,
                              MaterialPoints& points) {
  const MaterialTable table(materials);
  const auto material = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.material);
  const auto position = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.position);
  std::vector<Real> pressure(points.count);
  const bool from_table = !spec.pore_pressure_table.empty();
  const Polyline surface =
      from_table ? Polyline(spec.pore_pressure_table, "Initialisation/Pore Pressure Table")
                 : Polyline(spec.phreatic_surface, "Initialisation/Phreatic Surface (m)");
  for (int p = 0; p < points.count; ++p) {
    const MaterialSpec& m = materials[material(p)];
    if (m.phase == PhaseModel::Dry) continue;
    pressure[p] = from_table
                      ? surface.at(position(p, 1))
                      : hydrostaticPressure(m.liquid.density, gravity, surface.at(position(p, 0)),
                                            position(p, 1), spec.max_suction);
  }
  setPointLiquidPressures(table, pressure, points);
  if (from_table)
    return "initial state: p_L from Initialisation/Pore Pressure Table, stress per "
           "material (Initial State)";
  return std::string("initial state: hydrostatic p_L from the phreatic surface") +
         (spec.max_suction >= 0 ? ", suction capped" : "") +
         ", stress per material (Initial State)";
}

}  // namespace argine
