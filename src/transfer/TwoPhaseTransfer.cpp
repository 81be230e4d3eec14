#include "argine/transfer/TwoPhaseTransfer.hpp"

#include <Kokkos_ScatterView.hpp>

#include "argine/materials/ObjectiveStressRate.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/CompensatedSum.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/NodeRecords.hpp"
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

/// Where a P2G kernel adds a node's contributions: the node's packed row of
/// NodeRecords::sums_i, through a ScatterView access (plain adds on Serial)...
template <class Access>
struct PackedNodeSum {
  Access& access;
  int i;
  KOKKOS_FORCEINLINE_FUNCTION void add(int slot, Real v) const { access(i, slot) += v; }
};

template <class Access>
struct PackedSums {
  Access& access;
  KOKKOS_FORCEINLINE_FUNCTION PackedNodeSum<Access> node(int i) const { return {access, i}; }
};

/// ... or the GridFields sums `hi`, compensated with their low parts in `lo` (reproducible
/// sums, CompensatedSum.hpp; Serial only, so plain references). `slot` is a constant where
/// the kernels call this, so the switch folds away.
struct CompensatedNodeSum {
  const GridFields& hi;
  const GridFields& lo;
  int i;
  KOKKOS_FORCEINLINE_FUNCTION void add(int slot, Real v) const {
    switch (slot) {
      case kSumMassSolid:
        return addCompensated(hi.mass_solid_i(i), lo.mass_solid_i(i), v);
      case kSumMassLiquid:
        return addCompensated(hi.mass_liquid_i(i), lo.mass_liquid_i(i), v);
      case kSumMassIntrinsic:
        return addCompensated(hi.mass_liquid_intrinsic_i(i), lo.mass_liquid_intrinsic_i(i), v);
      case kSumDrag:
        return addCompensated(hi.drag_i(i), lo.drag_i(i), v);
      case kSumVolumeLiquid:
        return addCompensated(hi.volume_liquid_i(i), lo.volume_liquid_i(i), v);
    }
    for (int d = 0; d < kDim; ++d) {
      if (slot == kSumMomentumSolid + d)
        return addCompensated(hi.momentum_solid_i(i, d), lo.momentum_solid_i(i, d), v);
      if (slot == kSumMomentumLiquid + d)
        return addCompensated(hi.momentum_liquid_i(i, d), lo.momentum_liquid_i(i, d), v);
      if (slot == kSumForceMixture + d)
        return addCompensated(hi.force_mixture_i(i, d), lo.force_mixture_i(i, d), v);
      if (slot == kSumForceLiquid + d)
        return addCompensated(hi.force_liquid_i(i, d), lo.force_liquid_i(i, d), v);
    }
  }
};

struct CompensatedSums {
  GridFields hi, lo;
  KOKKOS_FORCEINLINE_FUNCTION CompensatedNodeSum node(int i) const { return {hi, lo, i}; }
};

/// Runs body(p, sums, r0, r1, n) for every point, with `sums` the packed rows of `records` or,
/// with `compensation`, the compensated GridFields sums (grid, *compensation), and r0, r1, n
/// the body's totals, summed in point order (Serial); the packed sums are added to `grid` at
/// the active nodes afterwards (all slots, or the momenta alone).
template <class Body>
KineticTotals scatterFromPoints(const char* name, int count, const Body& body,
                                const ActiveNodes& active, NodeRecords& records, GridFields& grid,
                                const GridFields* compensation, bool momenta_only) {
  KineticTotals totals;
  const auto policy = Kokkos::RangePolicy<ExecSpace>(0, count);
  if (compensation) {
    const CompensatedSums sums{grid, *compensation};
    Kokkos::parallel_reduce(
        name, policy,
        KOKKOS_LAMBDA(const int p, Real& r0, Real& r1, int& n) { body(p, sums, r0, r1, n); },
        totals.solid, totals.liquid, totals.non_finite_points);
    return totals;
  }
  records.allocate(grid.numNodes());
  auto scatter = KE::create_scatter_view(records.sums_i);
  Kokkos::parallel_reduce(
      name, policy,
      KOKKOS_LAMBDA(const int p, Real& r0, Real& r1, int& n) {
        auto access = scatter.access();
        body(p, PackedSums<decltype(access)>{access}, r0, r1, n);
      },
      totals.solid, totals.liquid, totals.non_finite_points);
  KE::contribute(records.sums_i, scatter);
  if (momenta_only)
    addMomentumSumsToGrid(active, records, grid);
  else
    addNodeSumsToGrid(active, records, grid);
  return totals;
}

template <int kNodes>
void mapPointsToGridImpl(const MaterialPoints& points, const PointShapes& shapes,
                         const LiquidCarrying& liquid_m, Real gravity, const ActiveNodes& active,
                         NodeRecords& records, GridFields& grid, const GridFields* compensation) {
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

  const auto body = KOKKOS_LAMBDA(const int p, const auto& sums, Real&, Real&, int&) {
    const PointShape& shape = shape_p(p);
    if (shape.node[0] < 0) return;
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
      const auto node = sums.node(shape.node[a]);
      const Real N = shape.value[a];
      const Real dx = shape.gradient[a][0], dy = shape.gradient[a][1];
      node.add(kSumMassSolid, N * m_solid);
      node.add(kSumMomentumSolid, N * m_solid * vsx);
      node.add(kSumMomentumSolid + 1, N * m_solid * vsy);
      node.add(kSumForceMixture, -(sxx * dx + sxy * dy) * volume);
      node.add(kSumForceMixture + 1, -(sxy * dx + syy * dy) * volume + N * weight_mixture);
    }
    if (!wet) return;

    const Real rho = density_liquid_p(p);
    const Real m_intrinsic = rho * volume;  // 4.46
    // Darcy drag per unit liquid volume n S_L rho_L g / k (4.2-4.3, 4.45), g = 9.81.
    const Real drag =
        porosity_p(p) * saturation_p(p) * rho * kStandardGravity / conductivity_p(p) * volume;
    const Real pressure_volume = pressure_p(p) * volume;
    const Real weight_liquid = -m_intrinsic * gravity;  // 4.41 with M~_L
    const Real vlx = velocity_liquid_p(p, 0), vly = velocity_liquid_p(p, 1);
    for (int a = 0; a < kNodes; ++a) {
      const auto node = sums.node(shape.node[a]);
      const Real N = shape.value[a];
      node.add(kSumMassLiquid, N * m_liquid);
      node.add(kSumMassIntrinsic, N * m_intrinsic);
      node.add(kSumDrag, N * drag);
      node.add(kSumVolumeLiquid, N * volume);
      node.add(kSumMomentumLiquid, N * m_intrinsic * vlx);
      node.add(kSumMomentumLiquid + 1, N * m_intrinsic * vly);
      // -f_L^int = sum B^T p_L m V with p_L compression positive (4.43).
      node.add(kSumForceLiquid, shape.gradient[a][0] * pressure_volume);
      node.add(kSumForceLiquid + 1, shape.gradient[a][1] * pressure_volume + N * weight_liquid);
    }
  };
  scatterFromPoints("p2g_two_phase", points.count, body, active, records, grid, compensation,
                    false);
}

template <int kNodes>
KineticTotals updateVelocitiesAndMapMomentaImpl(const PointShapes& shapes,
                                                const LiquidCarrying& liquid_m,
                                                const ActiveNodes& active, Real dt,
                                                VelocityBlend blend, MaterialPoints& points,
                                                NodeRecords& records, GridFields& grid,
                                                const GridFields* compensation) {
  const auto shape_p = shapes.shape_p;
  const auto material_p = points.material;
  const auto volume_p = points.volume;
  const auto mass_solid_p = points.mass_solid;
  const auto mass_liquid_p = points.mass_liquid;
  const auto density_liquid_p = points.density_liquid;
  const auto velocity_solid_p = points.velocity_solid;
  const auto velocity_liquid_p = points.velocity_liquid;
  readVelocityUpdateValues(active, grid, records);
  const auto values_i = records.values_i;
  const Real pic_solid = blend.solid, pic_liquid = blend.liquid;
  const auto body = KOKKOS_LAMBDA(const int p, const auto& sums, Real& ks, Real& kl, int& bad) {
    const PointShape& shape = shape_p(p);
    if (shape.node[0] < 0) return;
    const bool wet = liquid_m(material_p(p)) != 0;
    // solid: FLIP v_p + dt sum N a_i, blended: + alpha (sum N v_i - v_p) (the header). Each
    // interpolation a loop of its own: the conditions are tested once per point, not per node.
    Real as[kDim] = {0, 0}, al[kDim] = {0, 0}, vs_grid[kDim] = {0, 0}, vl[kDim] = {0, 0};
    const auto interpolate = [&](int slot, Real sum[kDim]) {
      for (int a = 0; a < kNodes; ++a)
        for (int d = 0; d < kDim; ++d) sum[d] += shape.value[a] * values_i(shape.node[a], slot + d);
    };
    interpolate(kReadAccelerationSolid, as);
    if (pic_solid > 0 || (wet && pic_liquid > 0)) interpolate(kReadVelocitySolid, vs_grid);
    if (wet) interpolate(kReadAccelerationLiquid, al);
    if (wet && pic_liquid > 0) interpolate(kReadVelocityLiquid, vl);
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
    for (int a = 0; a < kNodes; ++a) {
      const auto node = sums.node(shape.node[a]);
      const Real N = shape.value[a];
      node.add(kSumMomentumSolid, N * ms * vsx);
      node.add(kSumMomentumSolid + 1, N * ms * vsy);
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
    const Real ml = density_liquid_p(p) * volume_p(p);
    for (int a = 0; a < kNodes; ++a) {
      const auto node = sums.node(shape.node[a]);
      const Real N = shape.value[a];
      node.add(kSumMomentumLiquid, N * ml * vlx);
      node.add(kSumMomentumLiquid + 1, N * ml * vly);
    }
  };
  return scatterFromPoints("g2p_velocities_p2g_momenta", points.count, body, active, records, grid,
                           compensation, true);
}

template <int kNodes>
void interpolateVelocityGradientsImpl(const MaterialPoints& points, const PointShapes& shapes,
                                      const LiquidCarrying& liquid_m, const ActiveNodes& active,
                                      const GridFields& grid, NodeRecords& records, Real dt,
                                      PointRates& rates) {
  const auto shape_p = shapes.shape_p;
  const auto material_p = points.material;
  records.allocate(grid.numNodes());
  readStrainValues(active, grid, records);
  const auto values_i = records.values_i;
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
          const Real vx = values_i(i, kReadStrainVelocitySolid),
                     vy = values_i(i, kReadStrainVelocitySolid + 1);
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
            const Real vlx = values_i(i, kReadStrainVelocityLiquid),
                       vly = values_i(i, kReadStrainVelocityLiquid + 1);
            const Real wx = vlx - values_i(i, kReadStrainVelocitySolid),
                       wy = vly - values_i(i, kReadStrainVelocitySolid + 1);
            const Real c = values_i(i, kReadStrainLiquidContent);
            divergence += vlx * dx + vly * dy;
            relative_divergence += wx * dx + wy * dy;
            w[0] += centre * wx;
            w[1] += centre * wy;
            content += centre * c;
            gradient[0] += c * dx;
            gradient[1] += c * dy;
          }
        }
        divergence_p(p) = dt * divergence;
        flux_divergence_p(p) =
            dt * (content * relative_divergence + gradient[0] * w[0] + gradient[1] * w[1]);
      });
}

}  // namespace

void mapPointsToGrid(const MaterialPoints& points, const PointShapes& shapes,
                     const LiquidCarrying& liquid_m, Real gravity, const ActiveNodes& active,
                     NodeRecords& records, GridFields& grid, const GridFields* compensation) {
  withNodeCount(shapes, [&](auto nodes) {
    mapPointsToGridImpl<decltype(nodes)::value>(points, shapes, liquid_m, gravity, active, records,
                                                grid, compensation);
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
                                                 NodeRecords& records, GridFields& grid,
                                                 const GridFields* compensation) {
  records.allocate(grid.numNodes());
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
    totals = updateVelocitiesAndMapMomentaImpl<decltype(count)::value>(
        shapes, liquid_m, active, dt, blend, points, records, grid, compensation);
  });
  return totals;
}

void interpolateVelocityGradients(const MaterialPoints& points, const PointShapes& shapes,
                                  const LiquidCarrying& liquid_m, const ActiveNodes& active,
                                  const GridFields& grid, NodeRecords& records, Real dt,
                                  PointRates& rates) {
  if (rates.count() != points.count) rates.allocate(points.count);
  withNodeCount(shapes, [&](auto nodes) {
    interpolateVelocityGradientsImpl<decltype(nodes)::value>(points, shapes, liquid_m, active, grid,
                                                             records, dt, rates);
  });
}

}  // namespace argine
