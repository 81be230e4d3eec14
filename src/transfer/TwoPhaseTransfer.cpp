#include "argine/transfer/TwoPhaseTransfer.hpp"

#include <Kokkos_ScatterView.hpp>

#include "argine/materials/ObjectiveStressRate.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/CompensatedSum.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace {

namespace KE = Kokkos::Experimental;

/// Calls f(std::integral_constant<int, nodes>) for the element node count of `shapes`.
template <class Function>
void withNodeCount(const PointShapes& shapes, Function&& f) {
  if (shapes.type == ElementType::Tri3)
    f(std::integral_constant<int, 3>{});
  else
    f(std::integral_constant<int, 4>{});
}

template <int kNodes, bool kCompensated>
void mapPointsToGridImpl(const MaterialPoints& points, const PointShapes& shapes,
                         const LiquidCarrying& liquid_m, Real gravity, GridFields& grid,
                         const GridFields& lo) {
  const auto shape_p = shapes.shape_p;
  const auto material_p = points.material;
  const auto volume_p = points.volume;
  const auto mass_solid_p = points.mass_solid;
  const auto mass_liquid_p = points.mass_liquid;
  const auto density_liquid_p = points.density_liquid;
  const auto porosity_p = points.porosity;
  const auto saturation_p = points.saturation;
  const auto conductivity_p = points.conductivity;
  const auto pressure_p = points.pressure_liquid;
  const auto stress_p = points.stress_effective;
  const auto velocity_solid_p = points.velocity_solid;
  const auto velocity_liquid_p = points.velocity_liquid;

  auto mass_solid_sv = KE::create_scatter_view(grid.mass_solid_i);
  auto mass_liquid_sv = KE::create_scatter_view(grid.mass_liquid_i);
  auto mass_intrinsic_sv = KE::create_scatter_view(grid.mass_liquid_intrinsic_i);
  auto drag_sv = KE::create_scatter_view(grid.drag_i);
  auto volume_liquid_sv = KE::create_scatter_view(grid.volume_liquid_i);
  auto momentum_solid_sv = KE::create_scatter_view(grid.momentum_solid_i);
  auto momentum_liquid_sv = KE::create_scatter_view(grid.momentum_liquid_i);
  auto force_mixture_sv = KE::create_scatter_view(grid.force_mixture_i);
  auto force_liquid_sv = KE::create_scatter_view(grid.force_liquid_i);
  const GridFields hi = grid;  // the sums themselves (compensated: with lo)

  Kokkos::parallel_for(
      "p2g_two_phase", Kokkos::RangePolicy<ExecSpace>(0, points.count), KOKKOS_LAMBDA(const int p) {
        const PointShape& shape = shape_p(p);
        if (shape.node[0] < 0) return;
        auto mass_solid_i = mass_solid_sv.access();
        auto momentum_solid_i = momentum_solid_sv.access();
        auto force_mixture_i = force_mixture_sv.access();

        const Real volume = volume_p(p);
        const Real m_solid = mass_solid_p(p);
        const bool wet = liquid_m(material_p(p)) != 0;
        const Real m_liquid = wet ? mass_liquid_p(p) : 0;
        // Bishop total stress, chi = S_L (4.5), p_L compression positive.
        const Real bishop = wet ? saturation_p(p) * pressure_p(p) : 0;
        const Real sxx = stress_p(p, XX) - bishop;
        const Real syy = stress_p(p, YY) - bishop;
        const Real sxy = stress_p(p, XY);
        const Real weight_mixture = -(m_solid + m_liquid) * gravity;  // 4.42, m_m = M_S + M_L
        const Real vsx = velocity_solid_p(p, 0), vsy = velocity_solid_p(p, 1);

        for (int a = 0; a < kNodes; ++a) {
          const int i = shape.node[a];
          const Real N = shape.value[a];
          const Real dx = shape.gradient[a][0], dy = shape.gradient[a][1];
          addToNode<kCompensated>(mass_solid_i, hi.mass_solid_i, lo.mass_solid_i, i, N * m_solid);
          addToNode<kCompensated>(momentum_solid_i, hi.momentum_solid_i, lo.momentum_solid_i, i, 0,
                                  N * m_solid * vsx);
          addToNode<kCompensated>(momentum_solid_i, hi.momentum_solid_i, lo.momentum_solid_i, i, 1,
                                  N * m_solid * vsy);
          addToNode<kCompensated>(force_mixture_i, hi.force_mixture_i, lo.force_mixture_i, i, 0,
                                  -(sxx * dx + sxy * dy) * volume);
          addToNode<kCompensated>(force_mixture_i, hi.force_mixture_i, lo.force_mixture_i, i, 1,
                                  -(sxy * dx + syy * dy) * volume + N * weight_mixture);
        }
        if (!wet) return;

        auto mass_liquid_i = mass_liquid_sv.access();
        auto mass_intrinsic_i = mass_intrinsic_sv.access();
        auto drag_i = drag_sv.access();
        auto volume_liquid_i = volume_liquid_sv.access();
        auto momentum_liquid_i = momentum_liquid_sv.access();
        auto force_liquid_i = force_liquid_sv.access();
        const Real rho = density_liquid_p(p);
        const Real m_intrinsic = rho * volume;  // 4.46
        // Darcy drag per unit liquid volume n S_L rho_L g / k (4.2-4.3, 4.45), g = 9.81.
        const Real drag =
            porosity_p(p) * saturation_p(p) * rho * kStandardGravity / conductivity_p(p) * volume;
        const Real pressure_volume = pressure_p(p) * volume;
        const Real weight_liquid = -m_intrinsic * gravity;  // 4.41 with M~_L
        const Real vlx = velocity_liquid_p(p, 0), vly = velocity_liquid_p(p, 1);
        for (int a = 0; a < kNodes; ++a) {
          const int i = shape.node[a];
          const Real N = shape.value[a];
          addToNode<kCompensated>(mass_liquid_i, hi.mass_liquid_i, lo.mass_liquid_i, i,
                                  N * m_liquid);
          addToNode<kCompensated>(mass_intrinsic_i, hi.mass_liquid_intrinsic_i,
                                  lo.mass_liquid_intrinsic_i, i, N * m_intrinsic);
          addToNode<kCompensated>(drag_i, hi.drag_i, lo.drag_i, i, N * drag);
          addToNode<kCompensated>(volume_liquid_i, hi.volume_liquid_i, lo.volume_liquid_i, i,
                                  N * volume);
          addToNode<kCompensated>(momentum_liquid_i, hi.momentum_liquid_i, lo.momentum_liquid_i, i,
                                  0, N * m_intrinsic * vlx);
          addToNode<kCompensated>(momentum_liquid_i, hi.momentum_liquid_i, lo.momentum_liquid_i, i,
                                  1, N * m_intrinsic * vly);
          // -f_L^int = sum B^T p_L m V with p_L compression positive (4.43).
          addToNode<kCompensated>(force_liquid_i, hi.force_liquid_i, lo.force_liquid_i, i, 0,
                                  shape.gradient[a][0] * pressure_volume);
          addToNode<kCompensated>(force_liquid_i, hi.force_liquid_i, lo.force_liquid_i, i, 1,
                                  shape.gradient[a][1] * pressure_volume + N * weight_liquid);
        }
      });

  KE::contribute(grid.mass_solid_i, mass_solid_sv);
  KE::contribute(grid.mass_liquid_i, mass_liquid_sv);
  KE::contribute(grid.mass_liquid_intrinsic_i, mass_intrinsic_sv);
  KE::contribute(grid.drag_i, drag_sv);
  KE::contribute(grid.volume_liquid_i, volume_liquid_sv);
  KE::contribute(grid.momentum_solid_i, momentum_solid_sv);
  KE::contribute(grid.momentum_liquid_i, momentum_liquid_sv);
  KE::contribute(grid.force_mixture_i, force_mixture_sv);
  KE::contribute(grid.force_liquid_i, force_liquid_sv);
}

template <int kNodes, bool kCompensated>
KineticTotals updateVelocitiesAndMapMomentaImpl(const PointShapes& shapes,
                                                const LiquidCarrying& liquid_m, Real dt,
                                                VelocityBlend blend, MaterialPoints& points,
                                                GridFields& grid, const GridFields& lo) {
  const auto shape_p = shapes.shape_p;
  const auto material_p = points.material;
  const auto volume_p = points.volume;
  const auto mass_solid_p = points.mass_solid;
  const auto mass_liquid_p = points.mass_liquid;
  const auto density_liquid_p = points.density_liquid;
  const auto velocity_solid_p = points.velocity_solid;
  const auto velocity_liquid_p = points.velocity_liquid;
  const auto acceleration_solid_i = grid.acceleration_solid_i;
  const auto acceleration_liquid_i = grid.acceleration_liquid_i;
  const auto velocity_solid_i = grid.velocity_solid_i;
  const auto velocity_liquid_i = grid.velocity_liquid_i;
  const Real pic_solid = blend.solid, pic_liquid = blend.liquid;
  auto momentum_solid_sv = KE::create_scatter_view(grid.momentum_solid_i);
  auto momentum_liquid_sv = KE::create_scatter_view(grid.momentum_liquid_i);
  const auto momentum_solid_hi = grid.momentum_solid_i, momentum_liquid_hi = grid.momentum_liquid_i;
  const auto momentum_solid_lo = lo.momentum_solid_i, momentum_liquid_lo = lo.momentum_liquid_i;
  Real kinetic_solid = 0, kinetic_liquid = 0;
  int non_finite = 0;
  Kokkos::parallel_reduce(
      "g2p_velocities_p2g_momenta", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p, Real& ks, Real& kl, int& bad) {
        const PointShape& shape = shape_p(p);
        if (shape.node[0] < 0) return;
        const bool wet = liquid_m(material_p(p)) != 0;
        // solid: FLIP v_p + dt sum N a_i, blended: + alpha (sum N v_i - v_p) (the header)
        Real as[kDim] = {0, 0}, al[kDim] = {0, 0}, vs_grid[kDim] = {0, 0}, vl[kDim] = {0, 0};
        for (int a = 0; a < kNodes; ++a) {
          const int i = shape.node[a];
          const Real N = shape.value[a];
          for (int d = 0; d < kDim; ++d) {
            as[d] += N * acceleration_solid_i(i, d);
            if (pic_solid > 0 || (wet && pic_liquid > 0)) vs_grid[d] += N * velocity_solid_i(i, d);
            if (wet) {
              al[d] += N * acceleration_liquid_i(i, d);
              if (pic_liquid > 0) vl[d] += N * velocity_liquid_i(i, d);
            }
          }
        }
        Real v_solid[kDim];
        for (int d = 0; d < kDim; ++d) {
          const Real v = velocity_solid_p(p, d);
          v_solid[d] = v + dt * as[d] + pic_solid * (vs_grid[d] - v);
          velocity_solid_p(p, d) = v_solid[d];
        }
        const Real vsx = v_solid[0], vsy = v_solid[1];
        const Real ms = mass_solid_p(p);
        ks += 0.5 * ms * (vsx * vsx + vsy * vsy);
        if (!(Kokkos::Experimental::isfinite(vsx) && Kokkos::Experimental::isfinite(vsy))) ++bad;
        auto momentum_solid_i = momentum_solid_sv.access();
        for (int a = 0; a < kNodes; ++a) {
          const int i = shape.node[a];
          const Real N = shape.value[a];
          addToNode<kCompensated>(momentum_solid_i, momentum_solid_hi, momentum_solid_lo, i, 0,
                                  N * ms * vsx);
          addToNode<kCompensated>(momentum_solid_i, momentum_solid_hi, momentum_solid_lo, i, 1,
                                  N * ms * vsy);
        }
        if (!wet) return;
        // liquid: the relative velocity w_p = v_L - v_S relaxes towards the grid's sum N w_i
        // (the header); with pic_liquid = 0 this is FLIP.
        Real v_liquid[kDim];
        for (int d = 0; d < kDim; ++d) {
          const Real flip = velocity_liquid_p(p, d) + dt * al[d];
          const Real relative_pic = v_solid[d] + vl[d] - vs_grid[d] + dt * (al[d] - as[d]);
          v_liquid[d] = pic_liquid > 0 ? flip + pic_liquid * (relative_pic - flip) : flip;
        }
        const Real vlx = v_liquid[0], vly = v_liquid[1];
        velocity_liquid_p(p, 0) = vlx;
        velocity_liquid_p(p, 1) = vly;
        kl += 0.5 * mass_liquid_p(p) * (vlx * vlx + vly * vly);
        if (!(Kokkos::Experimental::isfinite(vlx) && Kokkos::Experimental::isfinite(vly))) ++bad;
        auto momentum_liquid_i = momentum_liquid_sv.access();
        const Real ml = density_liquid_p(p) * volume_p(p);
        for (int a = 0; a < kNodes; ++a) {
          const int i = shape.node[a];
          const Real N = shape.value[a];
          addToNode<kCompensated>(momentum_liquid_i, momentum_liquid_hi, momentum_liquid_lo, i, 0,
                                  N * ml * vlx);
          addToNode<kCompensated>(momentum_liquid_i, momentum_liquid_hi, momentum_liquid_lo, i, 1,
                                  N * ml * vly);
        }
      },
      kinetic_solid, kinetic_liquid, non_finite);
  KE::contribute(grid.momentum_solid_i, momentum_solid_sv);
  KE::contribute(grid.momentum_liquid_i, momentum_liquid_sv);
  return KineticTotals{kinetic_solid, kinetic_liquid, non_finite};
}

template <int kNodes>
void interpolateVelocityGradientsImpl(const MaterialPoints& points, const PointShapes& shapes,
                                      const LiquidCarrying& liquid_m, const GridFields& grid,
                                      Real dt, PointRates& rates) {
  const auto shape_p = shapes.shape_p;
  const auto material_p = points.material;
  const auto velocity_solid_i = grid.velocity_solid_i;
  const auto velocity_liquid_i = grid.velocity_liquid_i;
  const auto liquid_content_i = grid.liquid_content_i;
  const auto strain_increment_p = rates.strain_increment_p;
  const auto divergence_p = rates.liquid_divergence_increment_p;
  const auto flux_divergence_p = rates.content_flux_divergence_increment_p;
  const auto displacement_increment_p = rates.displacement_increment_p;
  const auto spin_increment_p = rates.spin_increment_p;
  Kokkos::parallel_for(
      "g2p_velocity_gradients", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        const PointShape& shape = shape_p(p);
        if (shape.node[0] < 0) {
          for (int c = 0; c < kStressComponents; ++c) strain_increment_p(p, c) = 0;
          displacement_increment_p(p, 0) = displacement_increment_p(p, 1) = 0;
          spin_increment_p(p) = 0;
          divergence_p(p) = 0;
          flux_divergence_p(p) = 0;
          return;
        }
        Real L[kDim][kDim] = {{0, 0}, {0, 0}};  // L_jk = d v_S,j / d x_k
        Real v[kDim] = {0, 0};
        for (int a = 0; a < kNodes; ++a) {
          const int i = shape.node[a];
          const Real N = shape.value[a];
          const Real dx = shape.gradient[a][0], dy = shape.gradient[a][1];
          const Real vx = velocity_solid_i(i, 0), vy = velocity_solid_i(i, 1);
          L[0][0] += vx * dx;
          L[0][1] += vx * dy;
          L[1][0] += vy * dx;
          L[1][1] += vy * dy;
          v[0] += N * vx;
          v[1] += N * vy;
        }
        strain_increment_p(p, XX) = dt * L[0][0];
        strain_increment_p(p, YY) = dt * L[1][1];
        strain_increment_p(p, ZZ) = 0;                               // plane strain
        strain_increment_p(p, XY) = 0.5 * dt * (L[0][1] + L[1][0]);  // tensor shear
        spin_increment_p(p) = spinIncrement(dt, L[0][1], L[1][0]);   // Jaumann rotation
        displacement_increment_p(p, 0) = dt * v[0];
        displacement_increment_p(p, 1) = dt * v[1];

        Real divergence = 0, relative_divergence = 0, content = 0;
        Real w[kDim] = {0, 0}, gradient[kDim] = {0, 0};
        if (liquid_m(material_p(p)) != 0) {
          // c = rho_L n S_L and w = v_L - v_S enter the advective flux div(c w) (4.12, 4.16)
          // at the element centre (N = 1/kNodes), not at the point: per-point values differ
          // between rows of points in one element, a pressure mode the momentum equations
          // cannot see (a one-element-wide quad4 column shows it), which then grows.
          constexpr Real centre = Real(1) / kNodes;
          for (int a = 0; a < kNodes; ++a) {
            const int i = shape.node[a];
            const Real dx = shape.gradient[a][0], dy = shape.gradient[a][1];
            const Real vlx = velocity_liquid_i(i, 0), vly = velocity_liquid_i(i, 1);
            const Real wx = vlx - velocity_solid_i(i, 0), wy = vly - velocity_solid_i(i, 1);
            divergence += vlx * dx + vly * dy;
            relative_divergence += wx * dx + wy * dy;
            w[0] += centre * wx;
            w[1] += centre * wy;
            content += centre * liquid_content_i(i);
            gradient[0] += liquid_content_i(i) * dx;
            gradient[1] += liquid_content_i(i) * dy;
          }
        }
        divergence_p(p) = dt * divergence;
        flux_divergence_p(p) =
            dt * (content * relative_divergence + gradient[0] * w[0] + gradient[1] * w[1]);
      });
}

}  // namespace

void mapPointsToGrid(const MaterialPoints& points, const PointShapes& shapes,
                     const LiquidCarrying& liquid_m, Real gravity, GridFields& grid,
                     const GridFields* compensation) {
  withNodeCount(shapes, [&](auto nodes) {
    constexpr int kNodes = decltype(nodes)::value;
    if (compensation)
      mapPointsToGridImpl<kNodes, true>(points, shapes, liquid_m, gravity, grid, *compensation);
    else
      mapPointsToGridImpl<kNodes, false>(points, shapes, liquid_m, gravity, grid, grid);
  });
}

void computeNodalVelocities(const ActiveNodes& active, GridFields& grid) {
  const auto nodes = active.nodes();
  const GridFields g = grid;
  Kokkos::parallel_for(
      "nodal_velocities", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        const Real ms = g.mass_solid_i(i);
        for (int d = 0; d < kDim; ++d)
          g.velocity_solid_i(i, d) = ms > 0 ? g.momentum_solid_i(i, d) / ms : 0;
        const Real ml = g.mass_liquid_intrinsic_i(i);
        for (int d = 0; d < kDim; ++d)
          g.velocity_liquid_i(i, d) =
              ml > 0 ? g.momentum_liquid_i(i, d) / ml : g.velocity_solid_i(i, d);
        const Real vl = g.volume_liquid_i(i);
        g.liquid_content_i(i) = vl > 0 ? g.mass_liquid_i(i) / vl : 0;
      });
}

KineticTotals updatePointVelocitiesAndMapMomenta(const PointShapes& shapes,
                                                 const LiquidCarrying& liquid_m,
                                                 const ActiveNodes& active, Real dt,
                                                 VelocityBlend blend, MaterialPoints& points,
                                                 GridFields& grid, const GridFields* compensation) {
  const auto nodes = active.nodes();
  const auto momentum_solid_i = grid.momentum_solid_i;
  const auto momentum_liquid_i = grid.momentum_liquid_i;
  Kokkos::parallel_for(
      "zero_momenta", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        for (int d = 0; d < kDim; ++d) momentum_solid_i(i, d) = momentum_liquid_i(i, d) = 0;
      });
  KineticTotals totals;
  withNodeCount(shapes, [&](auto count) {
    constexpr int kNodes = decltype(count)::value;
    if (compensation)
      totals = updateVelocitiesAndMapMomentaImpl<kNodes, true>(shapes, liquid_m, dt, blend, points,
                                                               grid, *compensation);
    else
      totals = updateVelocitiesAndMapMomentaImpl<kNodes, false>(shapes, liquid_m, dt, blend, points,
                                                                grid, grid);
  });
  return totals;
}

void interpolateVelocityGradients(const MaterialPoints& points, const PointShapes& shapes,
                                  const LiquidCarrying& liquid_m, const GridFields& grid, Real dt,
                                  PointRates& rates) {
  if (rates.count() != points.count) rates.allocate(points.count);
  withNodeCount(shapes, [&](auto nodes) {
    interpolateVelocityGradientsImpl<decltype(nodes)::value>(points, shapes, liquid_m, grid, dt,
                                                             rates);
  });
}

}  // namespace argine
