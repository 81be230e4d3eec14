#include "argine/physics/HydraulicBoundaryStep.hpp"

#include <Kokkos_ScatterView.hpp>

#include "argine/core/UntrackedViews.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/CompensatedSum.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace {

namespace KE = Kokkos::Experimental;

template <class Family, bool kCompensated>
void mapBoundaryGradientsImpl(const MaterialPoints& points, const PointShapes& shapes,
                              const Kokkos::View<const PointMaterial*, MemSpace>& materials_m,
                              const Kokkos::View<const int*, MemSpace>& liquid_m,
                              const GridFields& grid, BoundaryGradientFields& fields,
                              const LowParts<BoundaryGradientFields>& lo) {
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto material_p = points.material;
  const auto volume_p = points.volume;
  const auto mass_solid_p = points.mass_solid;
  const auto mass_liquid_p = points.mass_liquid;
  const auto porosity_p = points.porosity;
  const auto saturation_p = points.saturation;
  const auto content_i = grid.liquid_content_i;
  auto gradient_sv = KE::create_scatter_view(fields.mass_gradient_i);
  auto weight_sv = KE::create_scatter_view(fields.flux_weight_i);
  auto wet_sv = KE::create_scatter_view(fields.wet_volume_i);
  auto volume_gradient_sv = KE::create_scatter_view(fields.volume_gradient_i);
  auto pressure_volume_sv = KE::create_scatter_view(fields.pressure_volume_i);
  const auto pressure_p = points.pressure_liquid;
  const bool surface_pressure = fields.with_surface_pressure;
  const BoundaryGradientFields hi = fields;
  using B = BoundaryGradientFields;
  const auto lo_gradient = lowPartsOf(lo, &B::mass_gradient_i);
  const auto lo_weight = lowPartsOf(lo, &B::flux_weight_i);
  const auto lo_wet = lowPartsOf(lo, &B::wet_volume_i);
  const auto lo_volume_gradient = lowPartsOf(lo, &B::volume_gradient_i);
  const auto lo_pressure_volume = lowPartsOf(lo, &B::pressure_volume_i);
  constexpr int kNodes = Family::kNodes;
  Kokkos::parallel_for(
      "p2g_boundary_gradients", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        typename Family::Record scratch;
        const auto& shape = Family::of(shapes, p, element_p, local_p, scratch);
        if (shape.node[0] < 0) return;
        const bool wet = liquid_m(material_p(p)) != 0;
        const Real m_mixture = mass_solid_p(p) + (wet ? mass_liquid_p(p) : 0);  // 4.51
        auto gradient_i = gradient_sv.access();
        for (int a = 0; a < kNodes; ++a)
          for (int d = 0; d < kDim; ++d)
            addToNode<kCompensated>(gradient_i, hi.mass_gradient_i, lo_gradient, shape.node[a], d,
                                    m_mixture * shape.gradient[a][d]);
        if (!wet) return;
        auto weight_i = weight_sv.access();
        auto wet_i = wet_sv.access();
        const Real volume = volume_p(p);
        const Real wet_volume = porosity_p(p) * saturation_p(p) * volume;
        for (int a = 0; a < kNodes; ++a)
          addToNode<kCompensated>(wet_i, hi.wet_volume_i, lo_wet, shape.node[a],
                                  shape.value[a] * wet_volume);
        if (surface_pressure) {
          auto volume_gradient_i = volume_gradient_sv.access();
          auto pressure_volume_i = pressure_volume_sv.access();
          const Real pressure_volume = pressure_p(p) * volume;
          for (int a = 0; a < kNodes; ++a) {
            addToNode<kCompensated>(pressure_volume_i, hi.pressure_volume_i, lo_pressure_volume,
                                    shape.node[a], shape.value[a] * pressure_volume);
            for (int d = 0; d < kDim; ++d)
              addToNode<kCompensated>(volume_gradient_i, hi.volume_gradient_i, lo_volume_gradient,
                                      shape.node[a], d, volume * shape.gradient[a][d]);
          }
        }
        if (materials_m(material_p(p)).mass_balance == MassBalanceForm::Complete) {
          // the weights with which the strain kernel's advective flux reads the nodes
          // (Family::fluxCentre: the element centre, or the centre of the point's grid cell)
          Real centre[kNodes], centre_gradient[kNodes][kDim];
          Family::fluxCentre(shapes, p, shape, centre, centre_gradient);
          Real c_centre = 0, grad_c[kDim] = {0, 0};
          for (int a = 0; a < kNodes; ++a) {
            const Real c = content_i(shape.node[a]);
            c_centre += centre[a] * c;
            grad_c[0] += c * centre_gradient[a][0];
            grad_c[1] += c * centre_gradient[a][1];
          }
          for (int a = 0; a < kNodes; ++a)
            for (int d = 0; d < kDim; ++d)
              addToNode<kCompensated>(
                  weight_i, hi.flux_weight_i, lo_weight, shape.node[a], d,
                  volume * (c_centre * centre_gradient[a][d] + centre[a] * grad_c[d]));
        } else {
          const Real m_liquid = mass_liquid_p(p);
          for (int a = 0; a < kNodes; ++a)
            for (int d = 0; d < kDim; ++d)
              addToNode<kCompensated>(weight_i, hi.flux_weight_i, lo_weight, shape.node[a], d,
                                      m_liquid * shape.gradient[a][d]);
        }
      });
  KE::contribute(fields.mass_gradient_i, gradient_sv);
  KE::contribute(fields.flux_weight_i, weight_sv);
  KE::contribute(fields.wet_volume_i, wet_sv);
  if (surface_pressure) {
    KE::contribute(fields.volume_gradient_i, volume_gradient_sv);
    KE::contribute(fields.pressure_volume_i, pressure_volume_sv);
  }
}

/// n_L = n S_L at node i, mapped from the points: sum N n S_L V / sum N V.
KOKKOS_INLINE_FUNCTION Real nodalLiquidFraction(Real wet_volume, Real volume) {
  return volume > 0 ? wet_volume / volume : 0;
}

}  // namespace

void BoundaryGradientFields::allocate(int num_nodes) {
  mass_gradient_i = Kokkos::View<Real* [kDim], MemSpace>("mass_gradient_i", num_nodes);
  flux_weight_i = Kokkos::View<Real* [kDim], MemSpace>("flux_weight_i", num_nodes);
  wet_volume_i = Kokkos::View<Real*, MemSpace>("wet_volume_i", num_nodes);
  volume_gradient_i = Kokkos::View<Real* [kDim], MemSpace>("volume_gradient_i", num_nodes);
  pressure_volume_i = Kokkos::View<Real*, MemSpace>("pressure_volume_i", num_nodes);
}

void BoundaryGradientFields::zero(const ActiveNodes& active) {
  const auto nodes = active.nodes();
  const auto g = mass_gradient_i, w = flux_weight_i;
  const auto v = wet_volume_i;
  const auto vg = volume_gradient_i;
  const auto pv = pressure_volume_i;
  const bool surface_pressure = with_surface_pressure;
  Kokkos::parallel_for(
      "zero_boundary_gradients", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        for (int d = 0; d < kDim; ++d) g(i, d) = w(i, d) = 0;
        v(i) = 0;
        if (surface_pressure) {
          for (int d = 0; d < kDim; ++d) vg(i, d) = 0;
          pv(i) = 0;
        }
      });
}

void mapBoundaryGradients(const MaterialPoints& points, const PointShapes& shapes,
                          const Kokkos::View<const PointMaterial*, MemSpace>& materials_m,
                          const Kokkos::View<const int*, MemSpace>& liquid_m,
                          const GridFields& grid, BoundaryGradientFields& fields,
                          const LowParts<BoundaryGradientFields>* compensation) {
  withShapeFamily(shapes, [&](auto family) {
    using Family = decltype(family);
    compensation ? mapBoundaryGradientsImpl<Family, true>(points, shapes, materials_m, liquid_m,
                                                          grid, fields, *compensation)
                 : mapBoundaryGradientsImpl<Family, false>(points, shapes, materials_m, liquid_m,
                                                           grid, fields, {});
  });
}

void foldCompensatedBoundarySums(const ActiveNodes& nodes, BoundaryGradientFields& f,
                                 const LowParts<BoundaryGradientFields>& lo) {
  using B = BoundaryGradientFields;
  foldCompensatedSums(nodes, f.mass_gradient_i, lowPartsOf(lo, &B::mass_gradient_i));
  foldCompensatedSums(nodes, f.flux_weight_i, lowPartsOf(lo, &B::flux_weight_i));
  foldCompensatedSums(nodes, f.wet_volume_i, lowPartsOf(lo, &B::wet_volume_i));
  if (!f.with_surface_pressure) return;
  foldCompensatedSums(nodes, f.volume_gradient_i, lowPartsOf(lo, &B::volume_gradient_i));
  foldCompensatedSums(nodes, f.pressure_volume_i, lowPartsOf(lo, &B::pressure_volume_i));
}

void addHydraulicLoads(const NodalLoads& loads, GridFields& grid) {
  const auto node = loads.node;
  const auto mixture = loads.mixture;
  const auto liquid = loads.liquid;
  const GridFields g = untracked(grid);
  Kokkos::parallel_for(
      "add_hydraulic_loads", Kokkos::RangePolicy<ExecSpace>(0, loads.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = node(j);  // each node once per list: plain adds are race-free
        if (!(g.mass_solid_i(i) > 0)) return;
        for (int d = 0; d < kDim; ++d) {
          g.force_mixture_i(i, d) += mixture(j, d);
          if (g.mass_liquid_intrinsic_i(i) > 0) g.force_liquid_i(i, d) += liquid(j, d);
        }
      });
}

namespace {

/// The correction at node i of entry j: the flux-weight form, or the thesis form where the
/// flux weight has no component in the directions the locks leave free; `constraints` the
/// node's NodalConstraintBits (locks and fixities). Returns q_net.
KOKKOS_INLINE_FUNCTION Real nodeCorrection(const FluxCorrectionList& c, int j, int i,
                                           const BoundaryGradientFields& fields,
                                           const GridFields& g, Real density, bool solid_moves,
                                           unsigned constraints, const Real vl[kDim],
                                           const Real vs[kDim], Real dvl[kDim], Real dvs[kDim]) {
  const Real normal[kDim] = {c.normal(j, 0), c.normal(j, 1)};
  const Real weight[kDim] = {fields.flux_weight_i(i, 0), fields.flux_weight_i(i, 1)};
  Real q_net = 0;
  if (fluxWeightCorrection(weight, density, c.face_length(j), g.mass_liquid_i(i), g.mass_solid_i(i),
                           solid_moves, constraints, vl, vs, c.q_out(j), dvl, dvs, q_net))
    return q_net;
  const Real n_liquid = nodalLiquidFraction(fields.wet_volume_i(i), g.volume_liquid_i(i));
  return relativeFluxCorrection(n_liquid, g.mass_liquid_i(i), g.mass_solid_i(i), solid_moves,
                                normal, vl, vs, c.q_out(j), dvl, dvs, constraints);
}

}  // namespace

void correctHydraulicAccelerations(const FluxCorrectionList& corrections,
                                   const BoundaryGradientFields& fields, Real dt, bool solid_moves,
                                   Real liquid_density, GridFields& grid,
                                   Kokkos::View<const unsigned*, MemSpace> constraints) {
  const bool has_locks = constraints.extent(0) > 0;
  const auto node = corrections.node;
  const auto kind = corrections.kind;
  const auto applied = corrections.applied;
  const auto normal_j = corrections.normal;
  const auto wet_i = fields.wet_volume_i;
  const FluxCorrectionList list = corrections;
  const BoundaryGradientFields f = fields;
  const GridFields g = untracked(grid);
  Kokkos::parallel_for(
      "correct_hydraulic_accelerations", Kokkos::RangePolicy<ExecSpace>(0, corrections.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = node(j);
        applied(j) = 0;
        const Real n_liquid = nodalLiquidFraction(wet_i(i), g.volume_liquid_i(i));
        const Real normal[kDim] = {normal_j(j, 0), normal_j(j, 1)};
        if (!(n_liquid > 0) || (normal[0] == 0 && normal[1] == 0)) return;
        Real vl[kDim], vs[kDim], dvl[kDim], dvs[kDim];
        for (int d = 0; d < kDim; ++d) {  // Sec. 4.2 step 2: the prediction
          vl[d] = g.velocity_liquid_i(i, d) + dt * g.acceleration_liquid_i(i, d);
          vs[d] = g.velocity_solid_i(i, d) + dt * g.acceleration_solid_i(i, d);
        }
        const unsigned locks = has_locks ? constraints(j) : 0u;
        const Real q_net =
            nodeCorrection(list, j, i, f, g, liquid_density, solid_moves, locks, vl, vs, dvl, dvs);
        if (!correctionApplies(kind(j), q_net)) return;  // step 3: the switch
        applied(j) = 1;
        for (int d = 0; d < kDim; ++d) {  // step 5: corrected accelerations
          g.acceleration_liquid_i(i, d) += dvl[d] / dt;
          g.acceleration_solid_i(i, d) += dvs[d] / dt;
        }
      });
}

void correctHydraulicVelocities(const FluxCorrectionList& corrections,
                                const BoundaryGradientFields& fields, bool solid_moves,
                                Real liquid_density, GridFields& grid,
                                Kokkos::View<const unsigned*, MemSpace> constraints) {
  const bool has_locks = constraints.extent(0) > 0;
  const auto node = corrections.node;
  const auto kind = corrections.kind;
  const auto applied = corrections.applied;
  const auto normal_j = corrections.normal;
  const auto wet_i = fields.wet_volume_i;
  const FluxCorrectionList list = corrections;
  const BoundaryGradientFields f = fields;
  const GridFields g = untracked(grid);
  Kokkos::parallel_for(
      "correct_hydraulic_velocities", Kokkos::RangePolicy<ExecSpace>(0, corrections.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = node(j);
        if (!applied(j)) {  // the same preconditions as on the accelerations
          const Real n_liquid = nodalLiquidFraction(wet_i(i), g.volume_liquid_i(i));
          if (!(n_liquid > 0) || (normal_j(j, 0) == 0 && normal_j(j, 1) == 0)) return;
        }
        Real vl[kDim], vs[kDim], dvl[kDim], dvs[kDim];
        for (int d = 0; d < kDim; ++d) {
          vl[d] = g.velocity_liquid_i(i, d);
          vs[d] = g.velocity_solid_i(i, d);
        }
        const Real q_net = nodeCorrection(list, j, i, f, g, liquid_density, solid_moves,
                                          has_locks ? constraints(j) : 0u, vl, vs, dvl, dvs);
        // A node the prediction left at p = 0 (outflow, or a saturated surface) is corrected
        // when the REMAPPED velocities, which the mass balance uses, take in more than the
        // condition allows: otherwise a seepage face passes every inflow the remap brings.
        if (!applied(j) && !correctionApplies(kind(j), q_net)) return;
        for (int d = 0; d < kDim; ++d) {
          g.velocity_liquid_i(i, d) += dvl[d];
          g.velocity_solid_i(i, d) += dvs[d];
        }
      });
}

std::vector<Real> boundaryFluxMasses(const NodeOwnership& ownership, int conditions,
                                     const ActiveNodes& active,
                                     Kokkos::View<const unsigned char*, MemSpace> free_side,
                                     const BoundaryGradientFields& fields, const GridFields& grid,
                                     Real dt, Kokkos::View<const Real*, MemSpace> returned_i,
                                     Kokkos::View<const unsigned char*, MemSpace> rank_owned,
                                     std::vector<CompensatedReal>* compensation) {
  std::vector<Real> masses(conditions + 2, 0.0);
  const auto weight_i = fields.flux_weight_i;
  const auto vl_i = grid.velocity_liquid_i;
  const auto vs_i = grid.velocity_solid_i;
  const bool returned = returned_i.extent(0) > 0;
  auto inflow = KOKKOS_LAMBDA(const int i) {  // -dt w_i . G_i, less what the points gave back
    const Real in = pointBalanceInflowAtNode(dt, vl_i, vs_i, weight_i, i);
    return returned ? in - returned_i(i) : in;
  };
  const bool sided = free_side.extent(0) > 0;
  auto inside = KOKKOS_LAMBDA(const int i) {
    return !sided || (free_side(i) & kNodeOnFreeSide) == 0;
  };
  const auto owned = ownership.node;
  const auto owner = ownership.owner;
  const bool masked = rank_owned.extent(0) > 0;
  const auto nodes = active.nodes();
  if (compensation) {  // reproducible sums: the same terms, binned, in one order (host)
    std::vector<CompensatedReal>& sums = *compensation;
    sums.assign(conditions + 2, CompensatedReal{});
    for (int j = 0; j < ownership.count(); ++j)
      if (owner(j) >= 0 && owner(j) < conditions && (!masked || rank_owned(owned(j))))
        sums[owner(j)].add(inflow(owned(j)));
    for (int j = 0; j < active.count(); ++j) {
      const Real in = inflow(nodes(j));
      sums[conditions].add(in);
      if (inside(nodes(j))) sums[conditions + 1].add(in);
    }
    for (int c = 0; c < conditions + 2; ++c) masses[c] = sums[c].value();
    return masses;
  }
  for (int c = 0; c < conditions; ++c) {
    Real sum = 0;
    Kokkos::parallel_reduce(
        "boundary_flux_of_condition", Kokkos::RangePolicy<ExecSpace>(0, ownership.count()),
        KOKKOS_LAMBDA(const int j, Real& s) {
          if (owner(j) == c && (!masked || rank_owned(owned(j)))) s += inflow(owned(j));
        },
        sum);
    masses[c] = sum;
  }
  Real total = 0, interior = 0;
  Kokkos::parallel_reduce(
      "boundary_flux_total", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j, Real& s, Real& t) {
        const Real in = inflow(nodes(j));
        s += in;
        if (inside(nodes(j))) t += in;
      },
      total, interior);
  masses[conditions] = total;
  masses[conditions + 1] = interior;
  return masses;
}

}  // namespace argine
