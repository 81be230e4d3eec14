#include "argine/physics/HeadLoadsThroughSoil.hpp"

#include <Kokkos_ScatterView.hpp>

#include "argine/core/UntrackedViews.hpp"
#include "argine/physics/PointBorneLoads.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace {

namespace KE = Kokkos::Experimental;

template <class Family, bool kCompensated>
void spreadImpl(const HeadPressureField& field, const MaterialPoints& points,
                const PointShapes& shapes, const Kokkos::View<const int*, MemSpace>& liquid_m,
                PointBorneLoadFields& fields) {
  const MaterialPoints pts = untracked(points);
  const auto hi = fields.spread_i;
  const auto lo = fields.spread_lo;
  auto spread_sv = KE::create_scatter_view(fields.spread_i);
  Kokkos::parallel_for(
      "head_loads_through_soil", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        // the point's pressures first: where the river's field is nil (above its level, most
        // points once it is drawn down) it stops before its shapes are read
        const Real y = pts.position(p, 1);
        Real p_mixture, dp_mixture, p_liquid = 0, dp_liquid = 0;
        field.mixture(y, p_mixture, dp_mixture);
        const bool wet = liquid_m(pts.material(p)) != 0;
        if (wet) field.liquid(y, p_liquid, dp_liquid);
        if (p_mixture == 0 && dp_mixture == 0 && p_liquid == 0 && dp_liquid == 0) return;
        typename Family::Record scratch;
        const auto& shape = Family::of(shapes, p, pts.element, pts.local, scratch);
        if (shape.node[0] < 0) return;
        const Real volume = pts.volume(p);
        auto spread_i = spread_sv.access();
        for (int a = 0; a < Family::kNodes; ++a) {
          const Real n = shape.value[a];
          const Real* grad = shape.gradient[a];
          // -V grad(N p^), grad p^ = (0, dp/dy)
          const Real f[2 * kDim] = {
              -volume * p_mixture * grad[0], -volume * (p_mixture * grad[1] + n * dp_mixture),
              -volume * p_liquid * grad[0], -volume * (p_liquid * grad[1] + n * dp_liquid)};
          for (int c = 0; c < 2 * kDim; ++c)
            if (f[c] != 0) addToNode<kCompensated>(spread_i, hi, lo, shape.node[a], c, f[c]);
        }
      });
  KE::contribute(fields.spread_i, spread_sv);
}

}  // namespace

void spreadHeadLoadsThroughSoil(const HeadPressureField& field, const MaterialPoints& points,
                                const PointShapes& shapes,
                                const Kokkos::View<const int*, MemSpace>& liquid_m,
                                PointBorneLoadFields& fields) {
  withShapeFamily(shapes, [&](auto family) {
    using Family = decltype(family);
    fields.compensated() ? spreadImpl<Family, true>(field, points, shapes, liquid_m, fields)
                         : spreadImpl<Family, false>(field, points, shapes, liquid_m, fields);
  });
}

}  // namespace argine
