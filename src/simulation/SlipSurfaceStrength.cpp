#include "argine/simulation/SlipSurfaceStrength.hpp"

#include <algorithm>
#include <cmath>

#include "argine/materials/SolidModel.hpp"

namespace argine {

BaseStrength slipSurfaceStrength(const MaterialSpec& material, SuctionStrength mode, Real phi_b,
                                 Real liquid_pressure, Real saturation) {
  BaseStrength strength;
  if (material.solid.model == SolidModel::LinearElastic) {
    strength.cohesion = kElasticCohesion;
    return strength;
  }
  const Real suction = std::max(-liquid_pressure, Real(0));
  strength.cohesion = material.solid.cohesion;
  strength.friction_angle = material.solid.friction_angle;
  switch (mode) {
    case SuctionStrength::None:
      break;
    case SuctionStrength::SolidModel: {
      const MohrCoulombStrength own = mohrCoulombStrength(material.solid, suction);
      strength.cohesion = own.cohesion;
      strength.friction_angle = own.friction_angle;
      strength.suction_strength = saturation * suction * std::tan(own.friction_angle);
      break;
    }
    case SuctionStrength::Vanapalli: {
      const RetentionSpec& r = material.retention;
      const Real span = r.saturation_max - r.saturation_min;
      const Real effective =
          span > 0 ? std::clamp((saturation - r.saturation_min) / span, Real(0), Real(1)) : 1;
      strength.suction_strength = suction * effective * std::tan(strength.friction_angle);
      break;
    }
    case SuctionStrength::Fredlund:
      strength.suction_strength = suction * std::tan(phi_b);
      break;
  }
  return strength;
}

}  // namespace argine
