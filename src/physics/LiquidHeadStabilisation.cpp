#include "argine/physics/LiquidHeadStabilisation.hpp"

#include "argine/core/UntrackedViews.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/PointLiquidExchange.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace {

/// At most this share of the way to the node planes per step (stability of the exchange).
constexpr Real kStableShare = 0.25;

/// The channels of the node centres (phi and x, y, averaged with the weights N_i g_p) and of
/// the node slopes (the point gradients, averaged with the same weights).
enum CentreChannel : int { kPhi, kX, kY, kCentreChannels };
enum SlopeChannel : int { kSlopeX, kSlopeY, kSlopeChannels };

/// Relative Tikhonov term of a point's gradient fit: where its nodes' centres lie on a line
/// the gradient along the line, none across it.
constexpr Real kFitRegularisation = 1e-12;

/// Node i's centre, m_i and its position (column 2c: the average of channel c, made once per
/// node by divideNodeSums).
struct NodeCentre {
  Real phi, x, y;
};
template <class Sums>
KOKKOS_INLINE_FUNCTION NodeCentre nodeCentre(const Sums& averages, int i) {
  return {averages(i, 2 * kPhi), averages(i, 2 * kX), averages(i, 2 * kY)};
}

/// The gradient of the plane through the centres of the point's nodes, least squares with
/// the weights N_i(x_p): exact for a linear phi (each centre lies on it), and through three
/// centres (a triangle) the plane itself.
template <class Shape, class Averages>
KOKKOS_INLINE_FUNCTION void centresGradient(const Shape& shape, int nodes, const Averages& averages,
                                            Real gradient[kDim]) {
  Real w = 0, mx = 0, my = 0, mphi = 0;
  for (int a = 0; a < nodes; ++a) {
    if (shape.value[a] == 0) continue;  // a grid stencil corner may have no sums
    const NodeCentre c = nodeCentre(averages, shape.node[a]);
    w += shape.value[a];
    mx += shape.value[a] * c.x;
    my += shape.value[a] * c.y;
    mphi += shape.value[a] * c.phi;
  }
  mx /= w;
  my /= w;
  mphi /= w;
  Real cxx = 0, cxy = 0, cyy = 0, cx_phi = 0, cy_phi = 0;
  for (int a = 0; a < nodes; ++a) {
    if (shape.value[a] == 0) continue;
    const NodeCentre c = nodeCentre(averages, shape.node[a]);
    const Real dx = c.x - mx, dy = c.y - my, dphi = c.phi - mphi;
    cxx += shape.value[a] * dx * dx;
    cxy += shape.value[a] * dx * dy;
    cyy += shape.value[a] * dy * dy;
    cx_phi += shape.value[a] * dx * dphi;
    cy_phi += shape.value[a] * dy * dphi;
  }
  gradient[0] = gradient[1] = 0;
  const Real trace = cxx + cyy;
  if (!(trace > 0)) return;  // all centres at one place: no slope to see
  const Real a11 = cxx + kFitRegularisation * trace, a22 = cyy + kFitRegularisation * trace;
  const Real det = a11 * a22 - cxy * cxy;
  gradient[0] = (a22 * cx_phi - cxy * cy_phi) / det;
  gradient[1] = (a11 * cy_phi - cxy * cx_phi) / det;
}

/// slope_pc(p, :) <- the gradient through the centres of the point's nodes.
template <class Family>
void gatherCentreGradients(const MaterialPoints& points, const PointShapes& shapes,
                           const AveragingScratch& centres, const AveragingScratch& slopes) {
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto node_averages = centres.node_sums;  // divided: divideNodeSums
  const auto mode_pc = slopes.mode_pc;
  const auto slope_pc = slopes.value_pc;
  Kokkos::parallel_for(
      "head_stabilisation_gradients", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        if (mode_pc(p, kSlopeX) == kAverageNone) return;
        typename Family::Record record;
        const auto& shape = Family::of(shapes, p, element_p, local_p, record);
        Real gradient[kDim];
        centresGradient(shape, Family::kNodes, node_averages, gradient);
        slope_pc(p, kSlopeX) = gradient[0];
        slope_pc(p, kSlopeY) = gradient[1];
      });
}

/// head_p(p) <- sum_i N_i(x_p) (m_i + b_i . (x_p - x_i)), the node planes at the point.
template <class Family>
void gatherNodePlanes(const MaterialPoints& points, const PointShapes& shapes,
                      const AveragingScratch& centres, const AveragingScratch& slopes,
                      Kokkos::View<Real*, MemSpace> head_p) {
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto position_p = points.position;
  const auto centre_averages = centres.node_sums;  // divided: divideNodeSums
  const auto slope_averages = slopes.node_sums;
  const auto mode_pc = centres.mode_pc;
  Kokkos::parallel_for(
      "head_stabilisation_planes", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        if (mode_pc(p, kPhi) == kAverageNone) return;
        typename Family::Record record;
        const auto& shape = Family::of(shapes, p, element_p, local_p, record);
        const Real x = position_p(p, 0), y = position_p(p, 1);
        Real value = 0;
        for (int a = 0; a < Family::kNodes; ++a) {
          if (shape.value[a] == 0) continue;
          const int i = shape.node[a];
          const NodeCentre c = nodeCentre(centre_averages, i);
          const Real bx = slope_averages(i, 2 * kSlopeX), by = slope_averages(i, 2 * kSlopeY);
          value += shape.value[a] * (c.phi + bx * (x - c.x) + by * (y - c.y));
        }
        head_p(p) = value;
      });
}

}  // namespace

LiquidHeadStabilisation::LiquidHeadStabilisation(const MaterialTable& table, int nodes,
                                                 NodalExchange* exchange)
    : exchange_(exchange) {
  for (int m = 0; m < table.count(); ++m) {
    const PointMaterial& material = table.host(m);
    active_ = active_ || (carriesLiquid(material.phase) && material.locking.head_stabilisation > 0);
  }
  if (!active_) return;
  centres_.allocateSums(kCentreChannels, 0, nodes);
  slopes_.allocateSums(kSlopeChannels, 0, nodes);
}

void LiquidHeadStabilisation::apply(const MaterialTable& table, const MaterialPoints& points,
                                    const PointShapes& shapes, const ActiveNodes& active,
                                    PointRates& rates, Real dt, Real gravity) {
  if (!active_) return;
  const int count = points.count;
  centres_.fitPoints(count);
  slopes_.fitPoints(count);
  const auto materials_m = table.materials();
  const MaterialPoints pts = untracked(points);
  const auto centre_pc = centres_.value_pc, slope_pc = slopes_.value_pc;
  const auto conductance_p = centres_.weight_p, slope_weight_p = slopes_.weight_p;
  const auto mode_pc = centres_.mode_pc, slope_mode_pc = slopes_.mode_pc;
  Kokkos::parallel_for(
      "head_stabilisation_in", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        const PointMaterial& material = materials_m(pts.material(p));
        const Real alpha = material.locking.head_stabilisation;
        for (int c = 0; c < kCentreChannels; ++c) {
          mode_pc(p, c) = kAverageNone;
          centre_pc(p, c) = 0;
        }
        for (int c = 0; c < kSlopeChannels; ++c) {
          slope_mode_pc(p, c) = kAverageNone;
          slope_pc(p, c) = 0;
        }
        conductance_p(p) = slope_weight_p(p) = 0;
        if (!carriesLiquid(material.phase) || alpha <= 0 || pts.element(p) < 0) return;
        const Real pressure = pts.pressure_liquid(p);
        const Real storage = pointLiquidStorage(material, pts, p);  // kg/Pa
        Real conductance = alpha * pointDarcyConductance(pts.conductivity(p));
        if (dt * conductance > kStableShare * storage) conductance = kStableShare * storage / dt;
        if (!(conductance > 0)) return;
        conductance_p(p) = slope_weight_p(p) = conductance;
        const Real y = pts.position(p, 1);
        centre_pc(p, kPhi) = piezometricPressure(material, pressure, y, gravity);
        centre_pc(p, kX) = pts.position(p, 0);
        centre_pc(p, kY) = y;
        for (int c = 0; c < kCentreChannels; ++c) mode_pc(p, c) = kAverageNodal;
        for (int c = 0; c < kSlopeChannels; ++c) slope_mode_pc(p, c) = kAverageNodal;
      });
  // The node centres (m_i, x_i), each point's gradient through its nodes' centres, the node
  // slopes b_i as their weighted averages, then the node planes at the points.
  // (Each node's centre and slope divided once, where the points would divide them at each of
  // their nodes: the same quotients, to the bit.)
  sumPointValues(points, shapes, active, centres_, exchange_);
  divideNodeSums(active, centres_);
  withShapeFamily(shapes, [&](auto family) {
    gatherCentreGradients<decltype(family)>(points, shapes, centres_, slopes_);
  });
  sumPointValues(points, shapes, active, slopes_, exchange_);
  divideNodeSums(active, slopes_);
  const auto head_p = Kokkos::subview(centre_pc, Kokkos::ALL, static_cast<int>(kPhi));
  withShapeFamily(shapes, [&](auto family) {
    gatherNodePlanes<decltype(family)>(points, shapes, centres_, slopes_, head_p);
  });
  const PointRates rts = rates;
  Kokkos::parallel_for(
      "head_stabilisation_out", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        if (mode_pc(p, kPhi) == kAverageNone) return;
        const PointMaterial& material = materials_m(pts.material(p));
        // The point's own phi (its p_L and position are unchanged since the first kernel)
        // against the node planes at the point, now in head_p.
        const Real own =
            piezometricPressure(material, pts.pressure_liquid(p), pts.position(p, 1), gravity);
        addPointLiquidMassChange(material, pts, rts, p, -dt * conductance_p(p) * (own - head_p(p)));
      });
}

}  // namespace argine
