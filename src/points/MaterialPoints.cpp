#include "argine/points/MaterialPoints.hpp"

namespace argine {

void MaterialPoints::allocate(int n) {
  count = n;
  id = View<int*>("id_p", n);
  element = View<int*>("element_p", n);
  local = View<Real* [kDim]>("local_p", n);
  position = View<Real* [kDim]>("position_p", n);
  initial_position = View<Real* [kDim]>("initial_position_p", n);
  material = View<int*>("material_p", n);
  displacement = View<Real* [kDim]>("displacement_p", n);
  velocity_solid = View<Real* [kDim]>("velocity_solid_p", n);
  velocity_liquid = View<Real* [kDim]>("velocity_liquid_p", n);
  affine_velocity_solid = View<Real* [kAffineComponents]>("affine_velocity_solid_p", n);
  affine_velocity_liquid = View<Real* [kAffineComponents]>("affine_velocity_liquid_p", n);
  rest_reference = View<Real* [kDim]>("rest_reference_p", n);
  volume = View<Real*>("volume_p", n);
  initial_volume = View<Real*>("initial_volume_p", n);
  mass_solid = View<Real*>("mass_solid_p", n);
  mass_liquid = View<Real*>("mass_liquid_p", n);
  porosity = View<Real*>("porosity_p", n);
  separation = View<Real*>("separation_p", n);
  pressure_liquid = View<Real*>("pressure_liquid_p", n);
  density_liquid = View<Real*>("density_liquid_p", n);
  saturation = View<Real*>("saturation_p", n);
  conductivity = View<Real*>("conductivity_p", n);
  stress_effective = View<Real* [kStressComponents]>("stress_effective_p", n);
  strain = View<Real* [kStressComponents]>("strain_p", n);
  deviatoric_strain = View<Real*>("deviatoric_strain_p", n);
  plastic_strain = View<Real*>("plastic_strain_p", n);
  plastic_state = View<int*>("plastic_state_p", n);
}

}  // namespace argine
