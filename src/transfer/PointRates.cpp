#include "argine/transfer/PointRates.hpp"

namespace argine {

void PointRates::allocate(int n) {
  strain_increment_p = View<Real* [kStressComponents]>("strain_increment_p", n);
  liquid_divergence_increment_p = View<Real*>("liquid_divergence_increment_p", n);
  content_flux_divergence_increment_p = View<Real*>("content_flux_divergence_increment_p", n);
  displacement_increment_p = View<Real* [kDim]>("displacement_increment_p", n);
  spin_increment_p = View<Real*>("spin_increment_p", n);
}

}  // namespace argine
