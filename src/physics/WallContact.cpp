#include "argine/physics/WallContact.hpp"

#include "argine/boundary/FrictionalContact.hpp"
#include "argine/core/UntrackedViews.hpp"
#include "argine/physics/MomentumBalance.hpp"
#include "argine/transfer/GridFields.hpp"

namespace argine {

void constrainWallContactAccelerations(const FrictionalContact& contact,
                                       const MomentumSettings& settings, Real dt,
                                       GridFields& grid) {
  if (contact.count() == 0) return;  // no wall: not even the kernel's captures
  const auto nodes = contact.nodes();
  const auto normals = contact.normals();
  const auto friction = contact.friction();
  const auto flags = contact.flags();
  const auto at_rest = contact.atRest();
  const GridFields g = untracked(grid);
  const bool fixed_skeleton = settings.fixed_skeleton;
  const bool liquid_with_solid = settings.liquid_with_solid;
  Kokkos::parallel_for(
      "wall_contact_accelerations", Kokkos::RangePolicy<ExecSpace>(0, contact.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        const Real mass_solid = g.mass_solid_i(i);
        if (!(mass_solid > 0)) return;  // no soil at the node (or not on this rank)
        const unsigned bits = flags(j);
        const bool has_liquid = g.mass_liquid_intrinsic_i(i) > 0;
        const bool locked = has_liquid && (liquid_with_solid || (bits & kContactImpermeable));
        const Real mass_liquid = locked ? g.mass_liquid_i(i) : 0;
        const Real n[kDim] = {normals(j, 0), normals(j, 1)};
        Real as[kDim] = {g.acceleration_solid_i(i, 0), g.acceleration_solid_i(i, 1)};
        Real al[kDim] = {g.acceleration_liquid_i(i, 0), g.acceleration_liquid_i(i, 1)};
        if (locked) {  // 1. one normal acceleration for both phases, momentum-weighted
          const Real shared = (mass_solid * (as[0] * n[0] + as[1] * n[1]) +
                               mass_liquid * (al[0] * n[0] + al[1] * n[1])) /
                              (mass_solid + mass_liquid);
          const Real target[kDim] = {shared * n[0], shared * n[1]};
          matchNormalComponent(target, n, as);
          matchNormalComponent(target, n, al);
        }
        if (fixed_skeleton) {
          as[0] = as[1] = 0;
          at_rest(j) = 1;
        } else {  // 2. Coulomb's projection of the trial velocity
          const Real vs[kDim] = {g.velocity_solid_i(i, 0), g.velocity_solid_i(i, 1)};
          const Real trial[kDim] = {vs[0] + dt * as[0], vs[1] + dt * as[1]};
          Real after[kDim];
          wallSolidVelocity(bits, trial, n,
                            solidFrictionCoefficient(friction(j), mass_solid, mass_liquid), after);
          for (int d = 0; d < kDim; ++d) as[d] = (after[d] - vs[d]) / dt;
          // For the velocity form (a second pass finds the trial velocity 0 and agrees).
          at_rest(j) = after[0] == 0 && after[1] == 0;
          holdFixedComponents(bits, as);  // 3.
        }
        if (liquid_with_solid) {  // 4.
          al[0] = as[0];
          al[1] = as[1];
        } else if (has_liquid) {
          wallLiquidComponents(bits, locked, n, as, al);
        }
        for (int d = 0; d < kDim; ++d) {
          g.acceleration_solid_i(i, d) = as[d];
          g.acceleration_liquid_i(i, d) = al[d];
        }
      });
}

}  // namespace argine
