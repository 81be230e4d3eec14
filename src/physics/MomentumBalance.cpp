#include "argine/physics/MomentumBalance.hpp"

#include "argine/boundary/NodalConstraints.hpp"
#include "argine/core/UntrackedViews.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"

namespace argine {

void solveLiquidMomentum(const ActiveNodes& active, const MomentumSettings& settings, Real dt,
                         GridFields& grid) {
  if (settings.liquid_with_solid) return;  // solveMixtureMomentum sets a_L = a_S
  const auto nodes = active.nodes();
  const GridFields g = untracked(grid);
  const Real alpha = settings.local_damping;
  const LocalDampingForm form = settings.local_damping_form;
  const Real scaling = settings.mass_scaling;
  if (settings.implicit_drag) {
    const bool fixed_skeleton = settings.fixed_skeleton;
    Kokkos::parallel_for(
        "solve_liquid_momentum_implicit_drag", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
        KOKKOS_LAMBDA(const int j) {
          const int i = nodes(j);
          const Real mass = g.mass_liquid_intrinsic_i(i);
          if (!(mass > 0)) {
            g.acceleration_liquid_i(i, 0) = g.acceleration_liquid_i(i, 1) = 0;
            return;
          }
          const Real solid_mass = scaling * g.mass_solid_i(i);
          // the solid follows the mixture equation (a_S != 0) where solveMixtureMomentum
          // solves it
          const bool coupled = !fixed_skeleton && solid_mass > 0;
          for (int d = 0; d < kDim; ++d) {
            const Real relative = g.velocity_liquid_i(i, d) - g.velocity_solid_i(i, d);
            g.acceleration_liquid_i(i, d) = implicitDragLiquidAcceleration(
                g.force_liquid_i(i, d), g.force_mixture_i(i, d), g.drag_i(i), relative,
                g.velocity_liquid_i(i, d), dt, scaling * mass, scaling * g.mass_liquid_i(i),
                solid_mass, coupled, alpha, form);
          }
        });
    return;
  }
  Kokkos::parallel_for(
      "solve_liquid_momentum", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        const Real mass = g.mass_liquid_intrinsic_i(i);
        if (!(mass > 0)) {  // only dry points here: no liquid equation
          g.acceleration_liquid_i(i, 0) = g.acceleration_liquid_i(i, 1) = 0;
          return;
        }
        const Real scaled_mass = scaling * mass;
        const Real inverse_mass = 1 / scaled_mass;
        for (int d = 0; d < kDim; ++d) {
          const Real relative = g.velocity_liquid_i(i, d) - g.velocity_solid_i(i, d);
          const Real force = g.force_liquid_i(i, d) - g.drag_i(i) * relative;
          const Real damped =
              dampedForce(form, alpha, force, g.velocity_liquid_i(i, d), scaled_mass, dt);
          g.acceleration_liquid_i(i, d) = damped * inverse_mass;
        }
      });
}

void solveMixtureMomentum(const ActiveNodes& active, const MomentumSettings& settings, Real dt,
                          GridFields& grid) {
  const auto nodes = active.nodes();
  const GridFields g = untracked(grid);
  const Real alpha = settings.local_damping;
  const LocalDampingForm form = settings.local_damping_form;
  const Real scaling = settings.mass_scaling;
  const bool fixed_skeleton = settings.fixed_skeleton;
  const bool liquid_with_solid = settings.liquid_with_solid;
  Kokkos::parallel_for(
      "solve_mixture_momentum", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        const Real mass = g.mass_solid_i(i);
        if (fixed_skeleton || !(mass > 0)) {
          g.acceleration_solid_i(i, 0) = g.acceleration_solid_i(i, 1) = 0;
          return;
        }
        if (liquid_with_solid) {  // one mixture equation: (M_S + M_L) a = f^ext - f^int
          const Real mixture_mass = scaling * (mass + g.mass_liquid_i(i));
          const Real inverse_mixture_mass = 1 / mixture_mass;
          for (int d = 0; d < kDim; ++d) {
            const Real force = g.force_mixture_i(i, d);
            const Real damped =
                dampedForce(form, alpha, force, g.velocity_solid_i(i, d), mixture_mass, dt);
            g.acceleration_solid_i(i, d) = g.acceleration_liquid_i(i, d) =
                damped * inverse_mixture_mass;
          }
          return;
        }
        const Real scaled_mass = scaling * mass;
        const Real inverse_mass = 1 / scaled_mass;
        const Real liquid_mass = scaling * g.mass_liquid_i(i);
        for (int d = 0; d < kDim; ++d) {
          const Real force = g.force_mixture_i(i, d) - liquid_mass * g.acceleration_liquid_i(i, d);
          const Real damped =
              dampedForce(form, alpha, force, g.velocity_solid_i(i, d), scaled_mass, dt);
          g.acceleration_solid_i(i, d) = damped * inverse_mass;
        }
      });
}

void moveLiquidWithSolid(const ActiveNodes& active, GridFields& grid) {
  const auto nodes = active.nodes();
  const GridFields g = untracked(grid);
  Kokkos::parallel_for(
      "move_liquid_with_solid", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        for (int d = 0; d < kDim; ++d) g.velocity_liquid_i(i, d) = g.velocity_solid_i(i, d);
      });
}

void constrainAccelerations(const NodalConstraints& constraints, const MomentumSettings& settings,
                            Real dt, GridFields& grid) {
  const auto nodes = constraints.nodes();
  const auto flags = constraints.flags();
  const GridFields g = untracked(grid);
  const Real alpha = settings.local_damping;
  const LocalDampingForm form = settings.local_damping_form;
  const Real scaling = settings.mass_scaling;
  const bool fixed_skeleton = settings.fixed_skeleton;
  const bool liquid_with_solid = settings.liquid_with_solid;
  const bool implicit_drag = settings.implicit_drag;
  Kokkos::parallel_for(
      "constrain_accelerations", Kokkos::RangePolicy<ExecSpace>(0, constraints.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        const unsigned bits = flags(j);
        const bool has_liquid = g.mass_liquid_intrinsic_i(i) > 0;
        const Real mixture_mass = scaling * (g.mass_solid_i(i) + g.mass_liquid_i(i));
        for (int d = 0; d < kDim; ++d) {
          const bool locked = has_liquid && (liquid_with_solid || (bits & liquidLockedBit(d)));
          const bool fixed = fixed_skeleton || (bits & solidFixedBit(d));
          if (locked && !fixed && mixture_mass > 0) {
            const Real force = g.force_mixture_i(i, d);
            const Real damped =
                dampedForce(form, alpha, force, g.velocity_solid_i(i, d), mixture_mass, dt);
            g.acceleration_solid_i(i, d) = g.acceleration_liquid_i(i, d) = damped / mixture_mass;
          }
          if (fixed) {
            g.acceleration_solid_i(i, d) = 0;
            if (locked) {
              g.acceleration_liquid_i(i, d) = 0;
            } else if (implicit_drag && has_liquid) {  // the liquid against a_S,d = 0
              const Real relative = g.velocity_liquid_i(i, d) - g.velocity_solid_i(i, d);
              g.acceleration_liquid_i(i, d) = implicitDragLiquidAcceleration(
                  g.force_liquid_i(i, d), 0, g.drag_i(i), relative, g.velocity_liquid_i(i, d), dt,
                  scaling * g.mass_liquid_intrinsic_i(i), 0, 0, false, alpha, form);
            }
          }
        }
      });
}

}  // namespace argine
