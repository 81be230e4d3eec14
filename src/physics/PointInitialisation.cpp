#include "argine/physics/PointInitialisation.hpp"

#include <sstream>

#include "argine/core/Error.hpp"
#include "argine/input/Deck.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/points/MaterialPoints.hpp"

namespace argine {

void checkMaterialsForExplicitSolver(const std::vector<MaterialSpec>& materials) {
  for (const MaterialSpec& spec : materials) {
    const std::string where = "Materials/" + spec.name;
    auto fail = [&](const std::string& key, const std::string& expected, Real found) {
      std::ostringstream out;
      out << "expected " << expected << ", got " << found;
      throw InputError(where + "/" + key, out.str());
    };
    if (!(spec.porosity > 0 && spec.porosity < 1)) fail("Porosity", "0 < n < 1", spec.porosity);
    if (!(spec.solid_density > 0)) fail("Solid Density", "a positive density", spec.solid_density);
    if (!carriesLiquid(spec.phase)) continue;
    if (!(spec.conductivity.saturated_conductivity > 0))
      fail("Conductivity", "a positive saturated conductivity (m/s) for a material with liquid",
           spec.conductivity.saturated_conductivity);
    if (!(spec.liquid.bulk_modulus > 0))
      fail("Liquid/Bulk Modulus", "a positive liquid bulk modulus", spec.liquid.bulk_modulus);
    if (!(spec.liquid.density > 0))
      fail("Liquid/Density", "a positive liquid density", spec.liquid.density);
  }
}

void initialisePointState(const std::vector<MaterialSpec>& materials, MaterialPoints& points) {
  checkMaterialsForExplicitSolver(materials);
  const MaterialTable table(materials);

  // Initial state per material (uniform within a material): p_L, sigma'_yy, K0, n0.
  Kokkos::View<Real* [4], MemSpace> initial_m("initial_state_m", materials.size());
  auto initial = Kokkos::create_mirror_view(initial_m);
  for (std::size_t m = 0; m < materials.size(); ++m) {
    initial(m, 0) = materials[m].initial.liquid_pressure;
    initial(m, 1) = materials[m].initial.vertical_effective_stress;
    initial(m, 2) = materials[m].initial.earth_pressure_coefficient;
    initial(m, 3) = materials[m].porosity;
  }
  Kokkos::deep_copy(initial_m, initial);

  const auto materials_m = table.materials();
  const MaterialPoints pts = points;
  Kokkos::parallel_for(
      "initialise_point_state", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        const int m = pts.material(p);
        const PointMaterial& material = materials_m(m);
        const Real n = initial_m(m, 3);
        const Real volume = pts.volume(p);
        pts.porosity(p) = n;
        pts.mass_solid(p) = (1 - n) * material.solid_density * volume;  // 4.48
        for (int d = 0; d < kDim; ++d) {
          pts.velocity_solid(p, d) = 0;
          pts.velocity_liquid(p, d) = 0;
          pts.displacement(p, d) = 0;
        }
        const Real vertical = initial_m(m, 1), k0 = initial_m(m, 2);
        pts.stress_effective(p, XX) = k0 * vertical;
        pts.stress_effective(p, YY) = vertical;
        pts.stress_effective(p, ZZ) = k0 * vertical;
        pts.stress_effective(p, XY) = 0;
        for (int c = 0; c < kStressComponents; ++c) pts.strain(p, c) = 0;
        pts.deviatoric_strain(p) = 0;
        pts.plastic_strain(p) = 0;
        pts.plastic_state(p) = 0;

        if (!carriesLiquid(material.phase)) {  // dry: no liquid unknowns at all
          pts.pressure_liquid(p) = 0;
          pts.density_liquid(p) = 0;
          pts.saturation(p) = 0;
          pts.conductivity(p) = 0;
          pts.mass_liquid(p) = 0;
          return;
        }
        const Real pressure = initial_m(m, 0);
        const Real density = liquidDensity(material.liquid, pressure);  // 4.13
        const LiquidState state = liquidState(material, pressure);
        pts.pressure_liquid(p) = pressure;
        pts.density_liquid(p) = density;
        pts.saturation(p) = state.saturation;
        pts.conductivity(p) = state.conductivity;
        pts.mass_liquid(p) = n * state.saturation * density * volume;  // 4.47
      });
}

}  // namespace argine
