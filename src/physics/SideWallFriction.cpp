#include "argine/physics/SideWallFriction.hpp"

#include <Kokkos_ScatterView.hpp>
#include <vector>

#include "argine/boundary/SideWalls.hpp"
#include "argine/core/UntrackedViews.hpp"
#include "argine/parallel/NodalExchange.hpp"
#include "argine/physics/MomentumBalance.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/CompensatedSum.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace {

namespace KE = Kokkos::Experimental;

/// The out-of-plane component of a stored stress (xx, yy, zz, xy).
constexpr int kStressZZ = 2;

template <class Family, bool kCompensated>
void mapResistanceImpl(const MaterialPoints& points, const PointShapes& shapes,
                       const SideWallParameters& walls, Kokkos::View<Real*, MemSpace> hi,
                       const LowParts<Kokkos::View<Real*, MemSpace>>& lo) {
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto volume_p = points.volume;
  const auto stress_p = points.stress_effective;
  const Real mu = walls.friction, width = walls.width;
  auto resistance_sv = KE::create_scatter_view(hi);
  Kokkos::parallel_for(
      "p2g_side_wall_resistance", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        typename Family::Record scratch;
        const auto& shape = Family::of(shapes, p, element_p, local_p, scratch);
        if (shape.node[0] < 0) return;  // lost point
        const Real resistance = volume_p(p) * sideWallResistance(stress_p(p, kStressZZ), mu, width);
        if (!(resistance > 0)) return;
        auto resistance_i = resistance_sv.access();
        for (int a = 0; a < Family::kNodes; ++a)
          addToNode<kCompensated>(resistance_i, hi, lo, shape.node[a], shape.value[a] * resistance);
      });
  KE::contribute(hi, resistance_sv);
}

}  // namespace

void SideWallFriction::configure(const std::optional<SideWallParameters>& walls, int num_nodes) {
  active_ = walls.has_value();
  if (!active_) return;
  walls_ = *walls;
  if (static_cast<int>(resistance_i_.extent(0)) != num_nodes) {
    resistance_i_ = Kokkos::View<Real*, MemSpace>("side_wall_resistance_i", num_nodes);
    resistance_lo_ = allocateLowParts(resistance_i_);
    stuck_i_ = Kokkos::View<unsigned char*, MemSpace>("side_wall_stuck_i", num_nodes);
  }
}

void SideWallFriction::mapResistance(const MaterialPoints& points, const PointShapes& shapes,
                                     const ActiveNodes& active, NodalExchange* exchange,
                                     bool reproducible) {
  if (!active_) return;
  const auto nodes = active.nodes();
  const auto hi = resistance_i_;
  const auto lo = resistance_lo_;
  Kokkos::parallel_for(
      "zero_side_wall_resistance", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        hi(nodes(j)) = 0;
        for (int k = 0; k < kLowParts; ++k) lo[k](nodes(j)) = 0;
      });
  withShapeFamily(shapes, [&](auto family) {
    using Family = decltype(family);
    reproducible ? mapResistanceImpl<Family, true>(points, shapes, walls_, hi, lo)
                 : mapResistanceImpl<Family, false>(points, shapes, walls_, hi, lo);
  });
  if (exchange) {
    if (reproducible) {
      std::vector<NodalFieldRef> lo_refs;
      for (int k = 0; k < kLowParts; ++k) lo_refs.push_back(nodalField(lo[k]));
      exchange->sumCompensated({nodalField(hi)}, lo_refs);
    } else
      exchange->sum({nodalField(hi)});
  }
  if (reproducible) foldCompensatedSums(active, resistance_i_, resistance_lo_);
}

void SideWallFriction::constrainAccelerations(const ActiveNodes& active,
                                              const MomentumSettings& settings, Real dt,
                                              GridFields& grid) {
  if (!active_ || settings.fixed_skeleton) return;
  const auto nodes = active.nodes();
  const auto resistance_i = resistance_i_;
  const auto stuck_i = stuck_i_;
  const GridFields g = untracked(grid);
  const bool liquid_with_solid = settings.liquid_with_solid;
  const Real scaling = settings.mass_scaling;
  Kokkos::parallel_for(
      "side_wall_accelerations", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        stuck_i(i) = 0;
        const Real resistance = resistance_i(i);
        const Real mass_solid = g.mass_solid_i(i);
        if (!(resistance > 0) || !(mass_solid > 0)) return;
        // the momentum the walls act on: the solid's (4.37 with a_L of 4.36 fixed), or the
        // mixture's when the liquid moves with the solid
        const Real mass =
            scaling * (liquid_with_solid ? mass_solid + g.mass_liquid_i(i) : mass_solid);
        const Real v[kDim] = {g.velocity_solid_i(i, 0), g.velocity_solid_i(i, 1)};
        const Real trial[kDim] = {v[0] + dt * g.acceleration_solid_i(i, 0),
                                  v[1] + dt * g.acceleration_solid_i(i, 1)};
        Real after[kDim];
        stuck_i(i) = frictionSlowedVelocity(trial, dt * resistance / mass, after);
        for (int d = 0; d < kDim; ++d) {
          g.acceleration_solid_i(i, d) = (after[d] - v[d]) / dt;
          if (liquid_with_solid) g.acceleration_liquid_i(i, d) = g.acceleration_solid_i(i, d);
        }
      });
}

void SideWallFriction::holdStuckNodes(const ActiveNodes& active, const MomentumSettings& settings,
                                      GridFields& grid) const {
  if (!active_ || settings.fixed_skeleton) return;
  const auto nodes = active.nodes();
  const auto stuck_i = stuck_i_;
  const GridFields g = untracked(grid);
  const bool liquid_with_solid = settings.liquid_with_solid;
  Kokkos::parallel_for(
      "side_wall_hold_stuck", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        if (!stuck_i(i)) return;
        for (int d = 0; d < kDim; ++d) {
          g.velocity_solid_i(i, d) = 0;
          if (liquid_with_solid) g.velocity_liquid_i(i, d) = 0;
        }
      });
}

}  // namespace argine
