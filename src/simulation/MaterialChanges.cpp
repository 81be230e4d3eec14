#include "argine/simulation/MaterialChanges.hpp"

#include <cstdio>

#include "argine/core/Error.hpp"

namespace argine {

namespace {

constexpr Real kDegreesPerRadian = 180.0 / 3.14159265358979323846;

std::string describe(const std::string& material, const char* what, Real from, Real to,
                     const char* unit) {
  char line[256];
  std::snprintf(line, sizeof line, "material '%s': %s %.6g -> %.6g %s", material.c_str(), what,
                from, to, unit);
  return line;
}

}  // namespace

std::vector<std::string> applyMaterialChanges(const std::string& stage,
                                              const std::vector<MaterialChangeSpec>& changes,
                                              std::vector<MaterialSpec>& materials) {
  std::vector<std::string> log;
  for (const MaterialChangeSpec& change : changes) {
    MaterialSpec* material = nullptr;
    for (auto& m : materials)
      if (m.name == change.material) material = &m;
    if (!material)
      throw InputError("Stages/" + stage + "/Material Changes/" + change.material,
                       "no material of that name");
    const std::string& name = material->name;
    auto set = [&](const std::optional<Real>& value, Real& target, const char* what,
                   const char* unit, Real shown = 1) {
      if (!value) return;
      log.push_back(describe(name, what, target * shown, *value * shown, unit));
      target = *value;
    };
    SolidSpec& solid = material->solid;
    set(change.youngs_modulus, solid.youngs_modulus, "Young's modulus", "Pa");
    set(change.poisson_ratio, solid.poisson_ratio, "Poisson's ratio", "");
    set(change.cohesion, solid.cohesion, "cohesion", "Pa");
    set(change.friction_angle, solid.friction_angle, "friction angle", "deg", kDegreesPerRadian);
    set(change.dilatancy_angle, solid.dilatancy_angle, "dilatancy angle", "deg", kDegreesPerRadian);
    set(change.tensile_strength, solid.tensile_strength, "tensile strength", "Pa");
    ConductivitySpec& conductivity = material->conductivity;
    const Real kappa_to_k =
        material->liquid.density * kStandardGravity / material->liquid.viscosity;
    if (change.intrinsic_permeability) {
      set(change.intrinsic_permeability, conductivity.intrinsic_permeability,
          "intrinsic permeability", "m2");
      conductivity.saturated_conductivity = conductivity.intrinsic_permeability * kappa_to_k;
    }
    if (change.saturated_conductivity) {
      set(change.saturated_conductivity, conductivity.saturated_conductivity,
          "saturated conductivity", "m/s");
      conductivity.intrinsic_permeability = conductivity.saturated_conductivity / kappa_to_k;
    }
  }
  return log;
}

}  // namespace argine
