#include "argine/transfer/TransferScheme.hpp"

#include <cmath>

namespace argine {

VelocityBlend gridShares(TransferScheme scheme, const VelocityBlend& blend, Real dt) {
  const bool affine = carriesAffineVelocity(scheme);
  // -expm1(-x) = 1 - exp(-x), exact to rounding for the small rate dt of a step
  const auto share = [&](Real rate, Real per_step) {
    return rate > 0 ? -std::expm1(-rate * dt) : affine ? Real(1) : per_step;
  };
  VelocityBlend shares;
  shares.solid = share(blend.solid_rate, blend.solid);
  shares.liquid = share(blend.liquid_rate, blend.liquid);
  return shares;
}

}  // namespace argine
