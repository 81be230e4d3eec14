#include "argine/physics/MaterialTable.hpp"

#include "argine/input/Deck.hpp"
#include "argine/materials/LinearElastic.hpp"

namespace argine {

MaterialTable::MaterialTable(const std::vector<MaterialSpec>& materials) {
  const int count = static_cast<int>(materials.size());
  materials_m_ = Kokkos::View<PointMaterial*, MemSpace>("materials_m", count);
  liquid_m_ = Kokkos::View<int*, MemSpace>("liquid_carrying_m", count);
  auto table = Kokkos::create_mirror_view(materials_m_);
  auto liquid = Kokkos::create_mirror_view(liquid_m_);
  for (int m = 0; m < count; ++m) {
    const MaterialSpec& spec = materials[m];
    PointMaterial material;
    material.phase = spec.phase;
    material.mass_balance = spec.mass_balance;
    material.tension_cracks = spec.tension_cracks;
    material.solid_density = spec.solid_density;
    material.solid = spec.solid;
    material.solid_constants = solidConstants(spec.solid);
    material.liquid = spec.liquid;
    material.retention = spec.retention;
    material.conductivity = spec.conductivity;
    material.constrained_modulus = constrainedModulus(spec.solid);
    material.locking = spec.locking;
    table(m) = material;
    liquid(m) = carriesLiquid(spec.phase) ? 1 : 0;
    host_.push_back(material);
  }
  Kokkos::deep_copy(materials_m_, table);
  Kokkos::deep_copy(liquid_m_, liquid);
}

}  // namespace argine
