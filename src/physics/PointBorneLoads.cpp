#include "argine/physics/PointBorneLoads.hpp"

#include <Kokkos_ScatterView.hpp>
#include <vector>

#include "argine/core/UntrackedViews.hpp"
#include "argine/parallel/NodalExchange.hpp"
#include "argine/physics/HydraulicBoundaryStep.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace {

namespace KE = Kokkos::Experimental;

/// A point's two weights: its mixture mass (4.51's m_m) and, if it carries liquid, its
/// volume (the intrinsic liquid mass rho_L V of 4.38 over a uniform rho_L).
struct PointWeights {
  Real mixture = 0;
  Real liquid = 0;
};

KOKKOS_INLINE_FUNCTION PointWeights weightsOf(const MaterialPoints& points, int p, bool wet) {
  return {points.mass_solid(p) + (wet ? points.mass_liquid(p) : 0), wet ? points.volume(p) : 0};
}

template <class Family, bool kCompensated>
void spreadImpl(const MaterialPoints& points, const PointShapes& shapes,
                const Kokkos::View<const int*, MemSpace>& liquid_m,
                const BoundaryGradientFields& boundary, const GridFields& grid,
                PointBorneLoadFields& fields) {
  const MaterialPoints pts = untracked(points);
  const auto load_i = fields.load_i;
  const auto hi = fields.spread_i;
  const auto lo = fields.spread_lo;
  // the nodes' sums of the points' weights: the lumped masses of P2G, complete over the ranks
  const auto mass_solid_i = grid.mass_solid_i;
  const auto mass_liquid_i = grid.mass_liquid_i;
  const auto volume_liquid_i = grid.volume_liquid_i;
  const auto gradient_i = boundary.mass_gradient_i;
  auto spread_sv = KE::create_scatter_view(fields.spread_i);
  Kokkos::parallel_for(
      "point_borne_load_spread", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        typename Family::Record scratch;
        // most points have no loaded node (loads sit on the surface's nodes): they stop here,
        // before their weights are read
        const int* node = Family::nodesOf(shapes, p, pts.element, pts.local, scratch);
        if (node[0] < 0) return;
        bool loaded = false;
        for (int a = 0; a < Family::kNodes; ++a)
          for (int c = 0; c < 2 * kDim; ++c) loaded = loaded || load_i(node[a], c) != 0;
        if (!loaded) return;
        const auto& shape = Family::of(shapes, p, pts.element, pts.local, scratch);
        const PointWeights w = weightsOf(pts, p, liquid_m(pts.material(p)) != 0);
        // the point's share of its nodes' loads, and its outward normal (4.51 interpolated)
        Real share[2 * kDim] = {0, 0, 0, 0};
        Real gradient[kDim] = {0, 0};
        for (int a = 0; a < Family::kNodes; ++a) {
          const int i = shape.node[a];
          for (int d = 0; d < kDim; ++d) gradient[d] += shape.value[a] * gradient_i(i, d);
          const Real mixture_i = mass_solid_i(i) + mass_liquid_i(i);
          const Real to_mixture = mixture_i > 0 ? shape.value[a] * w.mixture / mixture_i : 0;
          const Real to_liquid =
              volume_liquid_i(i) > 0 ? shape.value[a] * w.liquid / volume_liquid_i(i) : 0;
          for (int d = 0; d < kDim; ++d) {
            share[d] += to_mixture * load_i(i, d);
            share[kDim + d] += to_liquid * load_i(i, kDim + d);
          }
        }
        Real normal[kDim];
        outwardNormalOfMassGradient(gradient, normal);
        const Real reach = pointEdgeReach(pts.volume(p));
        auto spread_i = spread_sv.access();
        for (int a = 0; a < Family::kNodes; ++a) {
          // N_j(x_p + l n) to first order: partition of unity kept (sum grad N_j = 0)
          const Real at_edge = shape.value[a] + reach * (normal[0] * shape.gradient[a][0] +
                                                         normal[1] * shape.gradient[a][1]);
          for (int c = 0; c < 2 * kDim; ++c)
            addToNode<kCompensated>(spread_i, hi, lo, shape.node[a], c, at_edge * share[c]);
        }
      });
  KE::contribute(fields.spread_i, spread_sv);
}

}  // namespace

void PointBorneLoadFields::allocate(int num_nodes) {
  load_i = Kokkos::View<Real * [2 * kDim], MemSpace>("point_borne_load_i", num_nodes);
  spread_i = Kokkos::View<Real**, MemSpace>("point_borne_spread_i", num_nodes, 2 * kDim);
  compensateSums(compensated_);
}

void PointBorneLoadFields::compensateSums(bool on) {
  compensated_ = on;
  if (!on)
    spread_lo = {};
  else if (spread_lo[0].extent(0) != spread_i.extent(0))
    spread_lo = allocateLowParts(spread_i);
}

void PointBorneLoadFields::zero(const ActiveNodes& active) {
  const auto nodes = active.nodes();
  const auto load = load_i;
  const auto spread = spread_i;
  const auto lo = spread_lo;
  const bool compensated = compensated_;
  Kokkos::parallel_for(
      "zero_point_borne_loads", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        for (int c = 0; c < 2 * kDim; ++c) {
          load(i, c) = spread(i, c) = 0;
          if (compensated)
            for (int k = 0; k < kLowParts; ++k) lo[k](i, c) = 0;
        }
      });
}

void spreadPointBorneLoads(const NodalLoads& loads, const MaterialPoints& points,
                           const PointShapes& shapes,
                           const Kokkos::View<const int*, MemSpace>& liquid_m,
                           const BoundaryGradientFields& boundary, const GridFields& grid,
                           PointBorneLoadFields& fields) {
  // No load on this rank (the river's pressure through the soil, or no condition that
  // loads): every point would find no loaded node and add nothing.
  if (loads.count() == 0) return;
  const auto node = loads.node;
  const auto mixture = loads.mixture;
  const auto liquid = loads.liquid;
  const auto load_i = fields.load_i;
  Kokkos::parallel_for(
      "point_borne_loads_in", Kokkos::RangePolicy<ExecSpace>(0, loads.count()),
      KOKKOS_LAMBDA(const int j) {  // each node once per list
        for (int d = 0; d < kDim; ++d) {
          load_i(node(j), d) = mixture(j, d);
          load_i(node(j), kDim + d) = liquid(j, d);
        }
      });
  withShapeFamily(shapes, [&](auto family) {
    using Family = decltype(family);
    fields.compensated()
        ? spreadImpl<Family, true>(points, shapes, liquid_m, boundary, grid, fields)
        : spreadImpl<Family, false>(points, shapes, liquid_m, boundary, grid, fields);
  });
}

void sumPointBorneLoadsAtSharedNodes(NodalExchange* exchange, const ActiveNodes& active,
                                     PointBorneLoadFields& fields) {
  if (exchange) {
    if (fields.compensated()) {
      std::vector<NodalFieldRef> lo_refs;
      for (int k = 0; k < kLowParts; ++k) lo_refs.push_back(nodalField(fields.spread_lo[k]));
      exchange->sumCompensated({nodalField(fields.spread_i)}, lo_refs);
    } else
      exchange->sum({nodalField(fields.spread_i)});
  }
  if (fields.compensated()) foldCompensatedSums(active, fields.spread_i, fields.spread_lo);
}

void addPointBorneLoads(const PointBorneLoadFields& fields, const ActiveNodes& active,
                        GridFields& grid) {
  const auto nodes = active.nodes();
  const auto spread_i = fields.spread_i;
  const GridFields g = untracked(grid);
  Kokkos::parallel_for(
      "add_point_borne_loads", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        if (!(g.mass_solid_i(i) > 0)) return;
        for (int d = 0; d < kDim; ++d) {
          g.force_mixture_i(i, d) += spread_i(i, d);
          if (g.mass_liquid_intrinsic_i(i) > 0) g.force_liquid_i(i, d) += spread_i(i, kDim + d);
        }
      });
}

}  // namespace argine
