#include "PointVariables.hpp"

#include <algorithm>

#include "argine/output/PointsFile.hpp"

namespace argine {

namespace {
template <class V>
typename V::HostMirror onHost(const V& view) {
  auto host = Kokkos::create_mirror_view(view);
  Kokkos::deep_copy(host, view);
  return host;
}
}  // namespace

PointSnapshot::PointSnapshot(const MaterialPoints& points)
    : id(onHost(points.id)),
      material(onHost(points.material)),
      position(onHost(points.position)),
      displacement(onHost(points.displacement)),
      velocity_solid(onHost(points.velocity_solid)),
      velocity_liquid(onHost(points.velocity_liquid)),
      volume(onHost(points.volume)),
      porosity(onHost(points.porosity)),
      pressure_liquid(onHost(points.pressure_liquid)),
      saturation(onHost(points.saturation)),
      conductivity(onHost(points.conductivity)),
      stress_effective(onHost(points.stress_effective)),
      deviatoric_strain(onHost(points.deviatoric_strain)),
      plastic_strain(onHost(points.plastic_strain)),
      plastic_state(onHost(points.plastic_state)) {}

const std::vector<PointVariable>& pointVariables() {
  using S = const PointSnapshot&;
  static const std::vector<PointVariable> variables = {
      // Motion since the file's reference coordinates: ParaView's displacement.
      {"displ_x", [](S s, int p) { return s.position(p, 0) - s.reference_x[p]; }},
      {"displ_y", [](S s, int p) { return s.position(p, 1) - s.reference_y[p]; }},
      // The solid displacement field of the physics (reset between stages).
      {"displacement_x", [](S s, int p) { return s.displacement(p, 0); }},
      {"displacement_y", [](S s, int p) { return s.displacement(p, 1); }},
      {"velocity_solid_x", [](S s, int p) { return s.velocity_solid(p, 0); }},
      {"velocity_solid_y", [](S s, int p) { return s.velocity_solid(p, 1); }},
      {"velocity_liquid_x", [](S s, int p) { return s.velocity_liquid(p, 0); }},
      {"velocity_liquid_y", [](S s, int p) { return s.velocity_liquid(p, 1); }},
      {"pressure_liquid", [](S s, int p) { return s.pressure_liquid(p); }},
      // Suction s = -p_L where p_L < 0 (p_L compression positive, gas pressure zero).
      {"suction", [](S s, int p) { return std::max(Real(0), -s.pressure_liquid(p)); }},
      {"saturation", [](S s, int p) { return s.saturation(p); }},
      {"conductivity", [](S s, int p) { return s.conductivity(p); }},
      {"porosity", [](S s, int p) { return s.porosity(p); }},
      {"stress_eff_xx", [](S s, int p) { return s.stress_effective(p, XX); }},
      {"stress_eff_yy", [](S s, int p) { return s.stress_effective(p, YY); }},
      {"stress_eff_zz", [](S s, int p) { return s.stress_effective(p, ZZ); }},
      {"stress_eff_xy", [](S s, int p) { return s.stress_effective(p, XY); }},
      // Out-of-plane shear is zero in plane strain; written so ParaView makes a tensor.
      {"stress_eff_xz", [](S, int) { return Real(0); }},
      {"stress_eff_yz", [](S, int) { return Real(0); }},
      {"deviatoric_strain", [](S s, int p) { return s.deviatoric_strain(p); }},
      {"plastic_strain", [](S s, int p) { return s.plastic_strain(p); }},
      {"plastic_state", [](S s, int p) { return Real(s.plastic_state(p)); }},
      {"material", [](S s, int p) { return Real(s.material(p)); }},
      {"volume", [](S s, int p) { return s.volume(p); }},
      {"point_id", [](S s, int p) { return Real(s.id(p)); }},
  };
  return variables;
}

const std::vector<std::string>& pointVariableNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> result;
    for (const auto& variable : pointVariables()) result.emplace_back(variable.name);
    return result;
  }();
  return names;
}

}  // namespace argine
