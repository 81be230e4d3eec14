#include "argine/transfer/XpicFilter.hpp"

#include <string>

#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"

namespace argine {

namespace {

/// Nodal vectors of both phases (the solid's kDim components, then the liquid's).
using NodalPair = Kokkos::View<Real * [2 * kDim], MemSpace>;

/// filtered (+)= coefficient v of both phases at the active nodes (`assign`: =).
void accumulateNodalVelocities(const ActiveNodes& active, const GridFields& grid, Real coefficient,
                               bool assign, const XpicScratch& scratch) {
  const auto nodes = active.nodes();
  const auto vs = grid.velocity_solid_i, vl = grid.velocity_liquid_i;
  const auto filtered = scratch.filtered_i;
  Kokkos::parallel_for(
      "xpic_accumulate", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        for (int d = 0; d < kDim; ++d) {
          const Real solid = coefficient * vs(i, d), liquid = coefficient * vl(i, d);
          filtered(i, d) = assign ? solid : filtered(i, d) + solid;
          filtered(i, kDim + d) = assign ? liquid : filtered(i, kDim + d) + liquid;
        }
      });
}

/// target = a target + b source at the active nodes, both phases (a = 0: target = b source).
void combine(const ActiveNodes& active, const NodalPair& target, Real a, const NodalPair& source,
             Real b) {
  const auto nodes = active.nodes();
  Kokkos::parallel_for(
      "xpic_combine", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        for (int c = 0; c < 2 * kDim; ++c)
          target(i, c) = a == 0 ? b * source(i, c) : a * target(i, c) + b * source(i, c);
      });
}

/// The grid's nodal velocities of both phases to `vectors` (to_grid false) or back.
void exchangeNodalVelocities(const ActiveNodes& active, GridFields& grid, const NodalPair& vectors,
                             bool to_grid) {
  const auto nodes = active.nodes();
  const auto vs = grid.velocity_solid_i, vl = grid.velocity_liquid_i;
  Kokkos::parallel_for(
      "xpic_exchange", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        for (int d = 0; d < kDim; ++d) {
          if (to_grid) {
            vs(i, d) = vectors(i, d);
            vl(i, d) = vectors(i, kDim + d);
          } else {
            vectors(i, d) = vs(i, d);
            vectors(i, kDim + d) = vl(i, d);
          }
        }
      });
}

}  // namespace

void filterNodalVelocitiesXpic(const XpicPolynomial& polynomial, const PointShapes& shapes,
                               const LiquidCarrying& liquid_m, const ActiveNodes& active,
                               MaterialPoints& points, NodeRecords& records, GridFields& grid,
                               XpicScratch& scratch, const LowParts<GridFields>* compensation,
                               const std::function<void()>& complete_momenta) {
  const int order = polynomial.order;
  if (order <= 1) return;  // XPIC(1): v* = v^(1), PIC
  const bool chebyshev = polynomial.lower_eigenvalue > 0;
  const auto sized = [&](NodalPair& view, const char* label) {
    if (static_cast<int>(view.extent(0)) != grid.numNodes())
      view = NodalPair(std::string(label), grid.numNodes());
  };
  sized(scratch.filtered_i, "xpic_filtered_i");
  if (chebyshev) {
    sized(scratch.residual_i, "xpic_residual_i");
    sized(scratch.direction_i, "xpic_direction_i");
    sized(scratch.product_i, "xpic_product_i");
  }
  if (static_cast<int>(scratch.velocity_solid_p.extent(0)) < points.count) {
    scratch.velocity_solid_p = Kokkos::View<Real* [kDim], MemSpace>("xpic_vs_p", points.count);
    scratch.velocity_liquid_p = Kokkos::View<Real* [kDim], MemSpace>("xpic_vl_p", points.count);
  }
  const std::pair<int, int> own(0, points.count);
  const auto saved_solid = Kokkos::subview(scratch.velocity_solid_p, own, Kokkos::ALL);
  const auto saved_liquid = Kokkos::subview(scratch.velocity_liquid_p, own, Kokkos::ALL);
  const auto point_solid = Kokkos::subview(points.velocity_solid, own, Kokkos::ALL);
  const auto point_liquid = Kokkos::subview(points.velocity_liquid, own, Kokkos::ALL);
  Kokkos::deep_copy(saved_solid, point_solid);
  Kokkos::deep_copy(saved_liquid, point_liquid);
  TransferSettings round_trip;  // TPIC: v_p = S+ v, then its momenta to the grid (S)
  round_trip.scheme = TransferScheme::Tpic;
  // The grid's velocities v become S S+ v (the liquid content again as it was).
  const auto roundTrip = [&] {
    updatePointVelocitiesAndMapMomenta(shapes, liquid_m, active, 0.0, round_trip, points, records,
                                       grid, compensation);
    if (complete_momenta) complete_momenta();
    computeNodalVelocities(active, grid);
  };
  const NodalPair filtered = scratch.filtered_i;
  if (!chebyshev) {
    // (-1)^(k+1) C(m, k), k = 1 .. m: m, then c_k (m - k) / (k + 1) with the sign turned
    Real coefficient = order;
    accumulateNodalVelocities(active, grid, coefficient, true, scratch);
    for (int k = 1; k < order; ++k) {
      roundTrip();  // v^(k+1)
      coefficient = -coefficient * (order - k) / (k + 1);
      accumulateNodalVelocities(active, grid, coefficient, false, scratch);
    }
  } else {
    // Solve Q x = v^(1), Q = S S+, from x = 0 by two runs of k Chebyshev steps on [a, 1]
    // (Saad 2003, Iterative Methods for Sparse Linear Systems, Alg. 12.1), then j plain
    // (Richardson) steps: the residual is (I - Q)^j s_k(Q)^2 v^(1), and x = v* keeps
    // 1 - (1 - lambda)^j s_k(lambda)^2 of a mode (XpicFilter.hpp).
    const NodalPair residual = scratch.residual_i, direction = scratch.direction_i;
    const NodalPair product = scratch.product_i;
    const auto subtractRoundTripOf = [&](const NodalPair& v) {  // residual -= Q v
      exchangeNodalVelocities(active, grid, v, true);
      roundTrip();
      exchangeNodalVelocities(active, grid, product, false);
      combine(active, residual, 1, product, -1);
    };
    const int k = (order - 1) / 2, j = order - 2 * k;
    const Real a = polynomial.lower_eigenvalue;
    const Real theta = (1 + a) / 2, delta = (1 - a) / 2, sigma = theta / delta;
    exchangeNodalVelocities(active, grid, residual, false);  // r = v^(1), x = 0
    Kokkos::deep_copy(filtered, 0.0);
    for (int run = 0; run < 2 && k > 0; ++run) {
      Real rho = 1 / sigma;
      combine(active, direction, 0, residual, 1 / theta);
      for (int step = 0; step < k; ++step) {
        combine(active, filtered, 1, direction, 1);
        subtractRoundTripOf(direction);
        if (step + 1 < k) {
          const Real rho_next = 1 / (2 * sigma - rho);
          combine(active, direction, rho_next * rho, residual, 2 * rho_next / delta);
          rho = rho_next;
        }
      }
    }
    for (int step = 0; step < j; ++step) {
      combine(active, filtered, 1, residual, 1);
      if (step + 1 < j) subtractRoundTripOf(residual);
    }
  }
  exchangeNodalVelocities(active, grid, filtered, true);
  Kokkos::deep_copy(point_solid, saved_solid);
  Kokkos::deep_copy(point_liquid, saved_liquid);
}

}  // namespace argine
