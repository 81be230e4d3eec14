#include "argine/physics/VolumetricAveraging.hpp"

#include <Kokkos_ScatterView.hpp>
#include <algorithm>
#include <cstring>
#include <type_traits>

#include "argine/core/Lanes.hpp"
#include "argine/core/UntrackedViews.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/parallel/NodalExchange.hpp"
#include "argine/physics/AveragingPatches.hpp"
#include "argine/physics/BishopStress.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/PointValueAveraging.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"

namespace argine {

namespace {

// The deck's IncrementAveraging values are the modes of averagePointValues.
constexpr int kNone = static_cast<int>(IncrementAveraging::None);
constexpr int kNodal = static_cast<int>(IncrementAveraging::Nodal);
static_assert(kNone == kAverageNone && kNodal == kAverageNodal &&
              static_cast<int>(IncrementAveraging::Element) == kAverageElement);

}  // namespace

VolumetricAveraging::VolumetricAveraging(const MaterialTable& table, const Mesh& mesh,
                                         NodalExchange* exchange, MPI_Comm comm)
    : exchange_(exchange) {
  const int nodes = mesh.numNodes();
  AveragingUse strain, pressure;
  Real length = 0;      // one for every material with an element average (checkDeck)
  bool filter = false;  // the same
  for (int m = 0; m < table.count(); ++m) {
    const PointMaterial& material = table.host(m);
    length = std::max(length, material.locking.averaging_length);
    filter = filter || material.locking.checkerboard_filter;
    strain.add(static_cast<int>(material.locking.volumetric_strain));
    pressure.add(material.phase == PhaseModel::Saturated
                     ? static_cast<int>(material.locking.liquid_pressure)
                     : kNone);
  }
  strain_ = strain.any();
  pressure_ = pressure.any();
  AveragingUse mean_stress;  // the conjugate mean stress takes the volumetric strain's average
  for (int m = 0; m < table.count(); ++m)
    if (table.host(m).locking.conjugate_mean_stress)
      mean_stress.add(static_cast<int>(table.host(m).locking.volumetric_strain));
  conjugate_ = mean_stress.any();
  all_nodal_ = strain_;
  for (int m = 0; m < table.count(); ++m) {
    const PointMaterial& material = table.host(m);
    const auto mode = material.locking.volumetric_strain;
    all_nodal_ =
        all_nodal_ && (mode == IncrementAveraging::None ||
                       (mode == IncrementAveraging::Nodal && carriesLiquid(material.phase)));
  }
  if (all_nodal_) {
    nodal_sums_ = Kokkos::View<Real * [kChannels + 1], MemSpace>("averaging_nodal_sums", nodes);
    // per material: 1 where its points average (nodal, liquid-carrying), 0 where none
    nodal_m_ = Kokkos::View<int*, MemSpace>("averaging_nodal_m", table.count());
    auto host = Kokkos::create_mirror_view(nodal_m_);
    for (int m = 0; m < table.count(); ++m)
      host(m) = table.host(m).locking.volumetric_strain == IncrementAveraging::Nodal ? 1 : 0;
    Kokkos::deep_copy(nodal_m_, host);
  }
  int element_rows = mesh.numElements();
  Kokkos::View<const int*, MemSpace> row_e;  // empty: one row an element
  if (length > 0 && (strain.elements || pressure.elements)) {
    // (the scratches' views keep the map alive)
    const AveragingPatches patches = buildAveragingPatches(mesh, length);
    element_rows = patches.count;
    row_e = patches.patch_e;
    increments_.usePatches(patches.patch_e, comm);
    pressure_increments_.usePatches(patches.patch_e, comm);
    mean_stresses_.usePatches(patches.patch_e, comm);
  }
  if (filter && (strain.elements || pressure.elements)) {
    // An element's neighbours may belong to another rank. On several ranks each element is
    // made a patch of its own, whose sums are completed over the ranks like any patch's
    // (every rank then filters the whole mesh's rows; an element's sums come from one rank,
    // so the completed sums are its bits and the ranks give one rank's results).
    if (comm != MPI_COMM_NULL && row_e.extent(0) == 0) {
      Kokkos::View<int*, MemSpace> own("averaging_element_as_patch", element_rows);
      Kokkos::parallel_for(
          "averaging_element_as_patch", Kokkos::RangePolicy<ExecSpace>(0, element_rows),
          KOKKOS_LAMBDA(const int e) { own(e) = e; });
      row_e = own;
      increments_.usePatches(row_e, comm);
      pressure_increments_.usePatches(row_e, comm);
    }
    const RowNeighbours neighbours = buildRowNeighbours(mesh, row_e, element_rows);
    increments_.useCheckerboardFilter(neighbours.start, neighbours.rows, neighbours.most);
    pressure_increments_.useCheckerboardFilter(neighbours.start, neighbours.rows, neighbours.most);
  }
  if (strain_) increments_.allocateSums(kChannels, strain, element_rows, nodes);
  if (pressure_) pressure_increments_.allocateSums(1, pressure, element_rows, nodes);
  // never filtered (checkDeck: the filter's null space would be free)
  if (conjugate_) mean_stresses_.allocateSums(kMeanChannels, mean_stress, element_rows, nodes);
}

void VolumetricAveraging::averageStrainIncrements(const MaterialTable& table,
                                                  const MaterialPoints& points,
                                                  const PointShapes& shapes,
                                                  const ActiveNodes& active, PointRates& rates) {
  if (!strain_) return;
  if (all_nodal_ && !increments_.compensated())
    return averageNodalChannelsTogether(points, shapes, active, rates);
  const int count = points.count;
  increments_.fitPoints(count);
  const auto materials_m = table.materials();
  const auto material_p = points.material;
  const auto volume_p = points.volume;
  const auto element_p = points.element;
  const auto strain_increment_p = rates.strain_increment_p;
  const auto divergence_p = rates.liquid_divergence_increment_p;
  const auto flux_divergence_p = rates.content_flux_divergence_increment_p;
  const auto value_pc = increments_.value_pc;
  const auto weight_p = increments_.weight_p;
  const auto mode_pc = increments_.mode_pc;
  // At liquid-carrying points the relative divergence dt div(v_L - v_S) and the flux
  // divergence dt div(c w) get the same averaging as d eps_vol, so the pore pressure follows
  // S (B u_L) with one smoothing operator S for both phases. (Smoothing the solid's volume
  // change alone couples the phases through S - I in the liquid equation only: a
  // non-symmetric coupling that the explicit step amplifies.) The three are independent
  // (each read before any is written back): one averaging, one exchange.
  Kokkos::parallel_for(
      "averaging_increments_in", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        const PointMaterial& material = materials_m(material_p(p));
        const int mode = static_cast<int>(material.locking.volumetric_strain);
        const Real strain = strain_increment_p(p, XX) + strain_increment_p(p, YY);
        const int liquid_mode = carriesLiquid(material.phase) ? mode : kNone;
        weight_p(p) = volume_p(p);
        mode_pc(p, kFluxDivergence) = liquid_mode;
        value_pc(p, kFluxDivergence) = flux_divergence_p(p);
        mode_pc(p, kRelativeDivergence) = liquid_mode;
        value_pc(p, kRelativeDivergence) = divergence_p(p) - strain;
        mode_pc(p, kVolumetricStrain) = mode;
        value_pc(p, kVolumetricStrain) = strain;
      });
  averagePointValues(points, shapes, active, increments_, exchange_);
  Kokkos::parallel_for(
      "averaging_increments_out", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        if (element_p(p) < 0) return;
        if (mode_pc(p, kFluxDivergence) != kNone)
          flux_divergence_p(p) = value_pc(p, kFluxDivergence);
        if (mode_pc(p, kRelativeDivergence) != kNone)
          divergence_p(p) = value_pc(p, kRelativeDivergence);  // + the averaged d eps_vol below
        if (mode_pc(p, kVolumetricStrain) == kNone) return;
        const Real averaged = value_pc(p, kVolumetricStrain);
        const Real shift = averaged - (strain_increment_p(p, XX) + strain_increment_p(p, YY));
        strain_increment_p(p, XX) += shift / 2;
        strain_increment_p(p, YY) += shift / 2;
        // dt div v_L = averaged relative divergence + averaged d eps_vol.
        if (carriesLiquid(materials_m(material_p(p)).phase)) divergence_p(p) += averaged;
      });
}

namespace {

/// Point p's three increments in the order of VolumetricAveraging's channels: dt div(c w),
/// dt div(v_L - v_S) - d eps_vol and d eps_vol (averageStrainIncrements' "in" kernel).
KOKKOS_INLINE_FUNCTION void channelValues(const PointRates& rates, int p, Real q[3]) {
  const Real strain = rates.strain_increment_p(p, XX) + rates.strain_increment_p(p, YY);
  q[0] = rates.content_flux_divergence_increment_p(p);
  q[1] = rates.liquid_divergence_increment_p(p) - strain;
  q[2] = strain;
}

/// On one thread (Serial) a node's row of the nodal sums (three channels and the weight,
/// contiguous) is added and read as one Lanes value: per lane the same product and sum as
/// the scalar form, so the same bits (core/Lanes.hpp).
constexpr bool kRowsInRegister = std::is_same_v<ExecSpace, Kokkos::Serial>;
static_assert(3 + 1 == kLanes, "a row of the nodal sums is one Lanes value");

/// sums[0 .. kLanes) += add.
KOKKOS_FORCEINLINE_FUNCTION void addToRow(Real* sums, Lanes add) {
  Lanes value;
  std::memcpy(&value, sums, sizeof value);
  value = value + add;
  std::memcpy(sums, &value, sizeof value);
}

/// The nodal sums of the three channels and their shared weight (zeroed at the active nodes
/// first): per node the adds of scatterAverageSums, in point order.
template <class Family, class Sums>
void scatterNodalChannels(const MaterialPoints& points, const PointShapes& shapes,
                          Kokkos::View<const int*, MemSpace> nodal_m, const PointRates& rates,
                          Sums sums) {  // (contribute: not const)
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto material_p = points.material;
  const auto volume_p = points.volume;
  static_assert(!kRowsInRegister ||
                std::is_same_v<typename Sums::array_layout, Kokkos::LayoutRight>);
  auto scatter = Kokkos::Experimental::create_scatter_view(sums);
  Kokkos::parallel_for(
      "averaging_nodal_channels_scatter", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        if (element_p(p) < 0 || nodal_m(material_p(p)) == 0) return;
        const Real w = volume_p(p);
        Real q[3];
        channelValues(rates, p, q);
        Real wq[3];
        for (int c = 0; c < 3; ++c) wq[c] = w * q[c];
        typename Family::Record record;
        const auto& shape = Family::of(shapes, p, element_p, local_p, record);
        if constexpr (kRowsInRegister) {  // a node's row of four sums is one register
          const Lanes row = {wq[0], wq[1], wq[2], w};
          for (int a = 0; a < Family::kNodes; ++a)
            addToRow(&sums(shape.node[a], 0), splat<Lanes>(shape.value[a]) * row);
          return;
        }
        auto access = scatter.access();
        for (int a = 0; a < Family::kNodes; ++a) {
          const int i = shape.node[a];
          const Real N = shape.value[a];
          for (int c = 0; c < 3; ++c) access(i, c) += N * wq[c];
          access(i, 3) += N * w;
        }
      });
  Kokkos::Experimental::contribute(sums, scatter);
}

/// The nodal averages back at the points and into their increments (averageStrainIncrements'
/// gather and "out" kernel): d eps_xx, d eps_yy shifted by half the change of d eps_vol each,
/// dt div(c w) and dt div(v_L - v_S) = averaged relative divergence + averaged d eps_vol.
template <class Family, class Averages>
void gatherNodalChannels(const MaterialPoints& points, const PointShapes& shapes,
                         Kokkos::View<const int*, MemSpace> nodal_m, const Averages& averages,
                         const PointRates& rates) {
  const auto element_p = points.element;
  const auto local_p = points.local;
  const auto material_p = points.material;
  static_assert(!kRowsInRegister ||
                std::is_same_v<typename Averages::array_layout, Kokkos::LayoutRight>);
  Kokkos::parallel_for(
      "averaging_nodal_channels_gather", Kokkos::RangePolicy<ExecSpace>(0, points.count),
      KOKKOS_LAMBDA(const int p) {
        if (element_p(p) < 0 || nodal_m(material_p(p)) == 0) return;
        typename Family::Record record;
        const auto& shape = Family::of(shapes, p, element_p, local_p, record);
        Real average[4];
        if constexpr (kRowsInRegister) {  // the three channels (and the weight) at once
          Lanes sum = splat<Lanes>(0);
          for (int a = 0; a < Family::kNodes; ++a) {
            if (shape.value[a] == 0) continue;  // as below
            Lanes row;
            std::memcpy(&row, &averages(shape.node[a], 0), sizeof row);
            sum = sum + splat<Lanes>(shape.value[a]) * row;
          }
          std::memcpy(average, &sum, sizeof average);
        } else {
          for (int c = 0; c < 3; ++c) {
            average[c] = 0;
            for (int a = 0; a < Family::kNodes; ++a) {
              // a node of no weight may have no sums at all (a grid family's stencil corner)
              if (shape.value[a] == 0) continue;
              average[c] += shape.value[a] * averages(shape.node[a], c);
            }
          }
        }
        const Real shift =
            average[2] - (rates.strain_increment_p(p, XX) + rates.strain_increment_p(p, YY));
        rates.content_flux_divergence_increment_p(p) = average[0];
        rates.strain_increment_p(p, XX) += shift / 2;
        rates.strain_increment_p(p, YY) += shift / 2;
        rates.liquid_divergence_increment_p(p) = average[1] + average[2];
      });
}

}  // namespace

void VolumetricAveraging::averageNodalChannelsTogether(const MaterialPoints& points,
                                                       const PointShapes& shapes,
                                                       const ActiveNodes& active,
                                                       PointRates& rates) {
  const auto nodes = active.nodes();
  const auto sums = nodal_sums_;
  Kokkos::parallel_for(
      "averaging_nodal_channels_zero", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        for (int k = 0; k <= kChannels; ++k) sums(nodes(j), k) = 0;
      });
  withShapeFamily(shapes, [&](auto family) {
    scatterNodalChannels<decltype(family)>(points, shapes, nodal_m_, rates, sums);
  });
  // Several ranks: a shared node also has the other rank's points in its sums.
  if (exchange_) exchange_->sum({nodalField(sums)});
  Kokkos::parallel_for(
      "averaging_nodal_channels_divide", Kokkos::RangePolicy<ExecSpace>(0, active.count()),
      KOKKOS_LAMBDA(const int j) {
        const int i = nodes(j);
        for (int c = 0; c < kChannels; ++c) sums(i, c) /= sums(i, kChannels);
      });
  withShapeFamily(shapes, [&](auto family) {
    gatherNodalChannels<decltype(family)>(points, shapes, nodal_m_, sums, rates);
  });
}

void VolumetricAveraging::averageMeanStresses(const MaterialTable& table,
                                              const MaterialPoints& points,
                                              const PointShapes& shapes,
                                              const ActiveNodes& active) {
  if (!conjugate_) return;
  const int count = points.count;
  mean_stresses_.fitPoints(count);
  if (static_cast<int>(mean_shift_p_.extent(0)) != count)
    mean_shift_p_ = MeanStressShifts("averaging_mean_stress_shift", count);
  const auto materials_m = table.materials();
  const MaterialPoints pts = untracked(points);
  const auto value_pc = mean_stresses_.value_pc;
  const auto weight_p = mean_stresses_.weight_p;
  const auto mode_pc = mean_stresses_.mode_pc;
  const auto shift_p = mean_shift_p_;
  // kMixtureMean: the total in-plane mean stress, Bishop chi = S_L (4.5) as in the P2G;
  // kLiquidPressure: p_L, whose B^T p_L V is the liquid's force (4.43). Weight V, as d eps_vol's.
  Kokkos::parallel_for(
      "averaging_mean_stress_in", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        const PointMaterial& material = materials_m(pts.material(p));
        const bool wet = carriesLiquid(material.phase);
        // the operator that averages the point's d eps_vol (element, patch or nodal)
        const int mode = material.locking.conjugate_mean_stress
                             ? static_cast<int>(material.locking.volumetric_strain)
                             : kNone;
        const Real bishop =
            wet ? bishopPorePressure(pts.saturation(p), pts.pressure_liquid(p)) : Real(0);
        weight_p(p) = pts.volume(p);
        mode_pc(p, kMixtureMean) = mode;
        value_pc(p, kMixtureMean) =
            (pts.stress_effective(p, XX) + pts.stress_effective(p, YY)) / 2 - bishop;
        mode_pc(p, kLiquidPressure) = wet ? mode : kNone;
        value_pc(p, kLiquidPressure) = wet ? pts.pressure_liquid(p) : Real(0);
        // the point's own, until the averages come
        shift_p(p, kMixtureMean) = value_pc(p, kMixtureMean);
        shift_p(p, kLiquidPressure) = value_pc(p, kLiquidPressure);
      });
  averagePointValues(points, shapes, active, mean_stresses_, exchange_);
  Kokkos::parallel_for(
      "averaging_mean_stress_out", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        for (int c = 0; c < kMeanChannels; ++c)
          shift_p(p, c) = mode_pc(p, c) == kNone || pts.element(p) < 0
                              ? Real(0)
                              : value_pc(p, c) - shift_p(p, c);
      });
}

void VolumetricAveraging::rememberPressures(const MaterialPoints& points) {
  if (!pressure_) return;
  if (static_cast<int>(old_pressure_.extent(0)) != points.count)
    old_pressure_ = Kokkos::View<Real*, MemSpace>("averaging_old_pressure", points.count);
  Kokkos::deep_copy(old_pressure_, points.pressure_liquid);
}

void VolumetricAveraging::averagePressureIncrements(const MaterialTable& table,
                                                    const MaterialPoints& points,
                                                    const PointShapes& shapes,
                                                    const ActiveNodes& active) {
  if (!pressure_) return;
  const int count = points.count;
  pressure_increments_.fitPoints(count);
  const auto materials_m = table.materials();
  const MaterialPoints pts = untracked(points);
  const auto old_p = old_pressure_;
  const auto value_p = Kokkos::subview(pressure_increments_.value_pc, Kokkos::ALL, 0);
  const auto weight_p = pressure_increments_.weight_p;
  const auto mode_p = Kokkos::subview(pressure_increments_.mode_pc, Kokkos::ALL, 0);
  Kokkos::parallel_for(
      "averaging_pressure_in", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        const PointMaterial& material = materials_m(pts.material(p));
        mode_p(p) = material.phase == PhaseModel::Saturated
                        ? static_cast<int>(material.locking.liquid_pressure)
                        : kNone;
        weight_p(p) = pts.porosity(p) * pts.volume(p);
        value_p(p) = pts.pressure_liquid(p) - old_p(p);
      });
  averagePointValues(points, shapes, active, pressure_increments_, exchange_);
  Kokkos::parallel_for(
      "averaging_pressure_out", Kokkos::RangePolicy<ExecSpace>(0, count),
      KOKKOS_LAMBDA(const int p) {
        if (mode_p(p) == kNone || pts.element(p) < 0) return;
        const PointMaterial& material = materials_m(pts.material(p));
        const Real pressure = old_p(p) + value_p(p);
        const Real rho = liquidDensity(material.liquid, pressure);  // 4.13
        pts.pressure_liquid(p) = pressure;
        pts.density_liquid(p) = rho;
        pts.mass_liquid(p) = pts.porosity(p) * rho * pts.volume(p);  // S_L = 1
      });
}

}  // namespace argine
