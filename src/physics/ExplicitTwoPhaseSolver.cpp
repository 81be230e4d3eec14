#include "argine/physics/ExplicitTwoPhaseSolver.hpp"

#include <algorithm>
#include <cmath>
#include <set>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "argine/core/Error.hpp"
#include "argine/input/Deck.hpp"
#include "argine/materials/KernelMath.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/parallel/PointMigration.hpp"
#include "argine/parallel/RankDecomposition.hpp"
#include "argine/physics/DistributedStep.hpp"
#include "argine/physics/FreeSurfaceSuction.hpp"
#include "argine/physics/HeadLoadsThroughSoil.hpp"
#include "argine/physics/InteriorLiquidBalance.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/PointBorneLoads.hpp"
#include "argine/physics/PointInitialisation.hpp"
#include "argine/physics/PointUpdates.hpp"
#include "argine/physics/StabilityCheck.hpp"
#include "argine/physics/WallContact.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/points/Seeding.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"

namespace argine {

namespace {

/// Sum over the load entries of |load| with the components along solid-fixed directions
/// left out (N per m): what the loads can push the solid with (host, boundary-sized).
Real freeLoadMagnitude(const NodalLoads& loads, const NodalConstraints& constraints) {
  const auto node = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), loads.node);
  const auto mixture = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), loads.mixture);
  Real sum = 0;
  for (int j = 0; j < loads.count(); ++j) {
    const unsigned fixed = constraints.flagsOf(node(j));
    const Real x = (fixed & kSolidFixedX) ? Real(0) : mixture(j, 0);
    const Real y = (fixed & kSolidFixedY) ? Real(0) : mixture(j, 1);
    sum += std::hypot(x, y);
  }
  return sum;
}

}  // namespace

ExplicitTwoPhaseSolver::ExplicitTwoPhaseSolver(const Mesh& mesh, MaterialPoints& points,
                                               const std::vector<MaterialSpec>& materials)
    : mesh_(mesh),
      points_(points),
      table_(materials),
      locator_(mesh),
      element_maps_(mesh),
      nodes_in_use_(mesh.numNodes()),
      nodes_next_(mesh.numNodes()),
      free_boundary_(mesh),
      time_step_(mesh) {
  checkMaterialsForExplicitSolver(materials);
  transfer_.node_coordinates = mesh.coordinates;
  for (const auto& material : materials)
    if (material.phase != PhaseModel::Dry) {
      reference_liquid_density_ = material.liquid.density;
      carries_liquid_ = true;
      break;
    }
  boundary_fields_.allocate(mesh.numNodes());
  point_borne_loads_.allocate(mesh.numNodes());
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), mesh.coordinates);
  Real low[kDim] = {0, 0}, high[kDim] = {0, 0};
  for (int i = 0; i < mesh.numNodes(); ++i)
    for (int d = 0; d < kDim; ++d) {
      low[d] = i == 0 ? X(i, d) : std::min(low[d], X(i, d));
      high[d] = i == 0 ? X(i, d) : std::max(high[d], X(i, d));
    }
  mesh_size_ = std::hypot(high[0] - low[0], high[1] - low[1]);
  mesh_bottom_ = low[1];
  mesh_top_ = high[1];
  grid_.allocate(mesh.numNodes());
  rates_.allocate(points.count);
  evaluatePointShapes(mesh_, points_, shapes_);
  nodes_next_.rebuild(mesh_, points_, &shapes_, {});
  averaging_ = VolumetricAveraging(table_, mesh_);
  air_path_ = AirPath(table_, mesh_.numElements());
  head_stabilisation_ = LiquidHeadStabilisation(table_, mesh_.numNodes());
  element_seepage_ = IntraElementSeepage(table_, mesh_.numElements(), mesh_.numNodes());
}

void ExplicitTwoPhaseSolver::setMaterials(const std::vector<MaterialSpec>& materials) {
  checkMaterialsForExplicitSolver(materials);
  dropPreparedTimeStep();  // the criteria read the materials: evaluate them again
  time_step_.markStale();
  table_ = MaterialTable(materials);
  averaging_ =
      VolumetricAveraging(table_, mesh_, exchange_.get(), ranks_ ? ranks_->comm() : MPI_COMM_NULL);
  air_path_ = AirPath(table_, mesh_.numElements());
  head_stabilisation_ = LiquidHeadStabilisation(table_, mesh_.numNodes(), exchange_.get());
  element_seepage_ =
      IntraElementSeepage(table_, mesh_.numElements(), mesh_.numNodes(), exchange_.get());
  setReproducibleSums(reproducible_sums_);  // the new scratch compensated as the old
  held_liquid_state_renewed_ = false;
  // New retention or conductivity parameters: S_L and k of every liquid-carrying point.
  const auto materials_m = table_.materials();
  const MaterialPoints pts = points_;
  Kokkos::parallel_for(
      "refresh_liquid_state", Kokkos::RangePolicy<ExecSpace>(0, points_.count),
      KOKKOS_LAMBDA(const int p) {
        const PointMaterial& material = materials_m(pts.material(p));
        if (!carriesLiquid(material.phase)) return;
        const LiquidState state = saturationAndConductivity(material, pts.pressure_liquid(p));
        pts.saturation(p) = state.saturation;
        pts.conductivity(p) = state.conductivity;
      });
}

void ExplicitTwoPhaseSolver::beginStage(const StageSpec& stage) {
  stage_name_ = stage.name;
  if (stage.solver == SolverKind::ImplicitSeepage)
    throw InputError("Stages/" + stage.name + "/Solver",
                     "the explicit two-phase solver runs explicit, quasi-static and fixed "
                     "skeleton stages; implicit seepage needs the implicit solver");
  momentum_.local_damping = stage.local_damping;
  momentum_.local_damping_form = stage.local_damping_form;
  momentum_.fixity_keeps_relative_velocity = stage.fixity_keeps_relative_velocity;
  hydraulic_loads_at_points_ = stage.hydraulic_loads_at_points;
  interior_liquid_conservative_ = stage.interior_liquid_conservative && carries_liquid_;
  const bool suction_held =
      stage.free_surface_suction_held && carries_liquid_ && !stage.hold_liquid_pressure;
  boundary_fields_.with_surface_pressure = suction_held;
  for (int k = 0; k < kLowParts; ++k) boundary_lo_[k].with_surface_pressure = suction_held;
  if (interior_liquid_conservative_ &&
      static_cast<int>(liquid_made_inside_i_.extent(0)) != mesh_.numNodes())
    liquid_made_inside_i_ = Kokkos::View<Real*, MemSpace>("liquid_made_inside_i", mesh_.numNodes());
  momentum_.mass_scaling = stage.mass_scaling;
  transfer_.scheme = stage.transfer;
  transfer_.blend = stage.transfer == TransferScheme::Xpic  // the filtered v* in full
                        ? VelocityBlend{1, 1}
                        : VelocityBlend{stage.solid_pic_fraction, stage.liquid_pic_fraction,
                                        stage.solid_pic_rate, stage.liquid_pic_rate};
  transfer_.xpic = stage.xpic;
  dropPreparedTimeStep();
  momentum_.fixed_skeleton = stage.solver == SolverKind::FixedSkeleton;
  momentum_.liquid_with_solid = stage.hold_liquid_pressure;
  held_liquid_state_renewed_ = false;
  momentum_.implicit_drag = stage.implicit_drag;
  gravity_ = stage.gravity;
  time_step_.configure(stage.time_step, stage.mass_scaling, stage.name, stage.implicit_drag);
  boundaries_ = StageBoundaryConditions(mesh_, stage);
  side_walls_.configure(boundaries_.sideWalls(), mesh_.numNodes());
  hydraulic_ = HydraulicConditions(mesh_, stage, time_);  // tables count from the stage start
  // The atmosphere's rule needs liquid to act on, and a held p_L takes no flux.
  if (!carries_liquid_ || stage.hold_liquid_pressure) hydraulic_.dropAtmosphere();
  if (hydraulic_.atmosphere()) hydraulic_.setOtherLiquidRules(otherLiquidRules());
  liquid_rules_ = interior_liquid_conservative_ ? otherLiquidRules() : std::vector<unsigned char>();
  head_side_rules_ =
      hydraulic_.headsThroughSoil() ? otherLiquidRules() : std::vector<unsigned char>();
  boundary_flux_volumes_.assign(hydraulic_.conditions().size() + 2, 0.0);
  free_boundary_stale_ = true;
  hydraulic_plan_current_ = false;

  const MaterialPoints pts = points_;
  if (stage.reset_displacements)
    Kokkos::parallel_for(
        "reset_displacements", Kokkos::RangePolicy<ExecSpace>(0, points_.count),
        KOKKOS_LAMBDA(const int p) {
          for (int d = 0; d < kDim; ++d) {
            pts.displacement(p, d) = 0;
            pts.initial_position(p, d) = pts.position(p, d);
          }
        });
  if (momentum_.fixed_skeleton)
    Kokkos::parallel_for(
        "hold_skeleton", Kokkos::RangePolicy<ExecSpace>(0, points_.count),
        KOKKOS_LAMBDA(const int p) {
          for (int d = 0; d < kDim; ++d) pts.velocity_solid(p, d) = 0;
          for (int c = 0; c < kAffineComponents; ++c) pts.affine_velocity_solid(p, c) = 0;
        });
  if (momentum_.liquid_with_solid)  // held p_L: no relative flow from the first step on
    Kokkos::parallel_for(
        "liquid_with_solid", Kokkos::RangePolicy<ExecSpace>(0, points_.count),
        KOKKOS_LAMBDA(const int p) {
          for (int d = 0; d < kDim; ++d) pts.velocity_liquid(p, d) = pts.velocity_solid(p, d);
          for (int c = 0; c < kAffineComponents; ++c)
            pts.affine_velocity_liquid(p, c) = pts.affine_velocity_solid(p, c);
        });
  if (!carriesAffineVelocity(transfer_.scheme))  // a FLIP stage after an APIC one: no C_p
    Kokkos::parallel_for(
        "clear_affine_velocities", Kokkos::RangePolicy<ExecSpace>(0, points_.count),
        KOKKOS_LAMBDA(const int p) {
          for (int c = 0; c < kAffineComponents; ++c)
            pts.affine_velocity_solid(p, c) = pts.affine_velocity_liquid(p, c) = 0;
        });
  // The energy scale of the instability bound (stageEnergyScale): the points' energies now,
  // summed over the ranks (the loads are the same on every rank); the hydraulic loads and
  // the liquid inflow join it as the stage goes.
  stage_energies_ = pointEnergies(points_, table_, gravity_, mesh_bottom_);
  if (ranks_) {
    std::vector<Real> sums{stage_energies_.potential, stage_energies_.stored,
                           stage_energies_.kinetic};
    sumOverRanks(ranks_->comm(), sums);
    stage_energies_ = PointEnergies{sums[0], sums[1], sums[2]};
  }
  load_bound_ = boundaries_.totalLoadMagnitude();
  inflow_energy_ = 0;
  stage_started_ = true;
}

const TimeStepChoice& ExplicitTwoPhaseSolver::chooseTimeStep() {
  PhaseTimer timer(profile_, StepPhase::TimeStep);
  if (!ranks_) return time_step_.next(points_, table_);
  if (prepared_time_step_) {  // chosen at the end of the last step (prepareNextTimeStep)
    prepared_time_step_ = false;
    global_choice_ = candidate_.choice;
    return global_choice_;
  }
  global_choice_ = globalTimeStep(ranks_->comm(), localTimeStep());
  return global_choice_;
}

// ------------------------------------------------------------------ several ranks

void ExplicitTwoPhaseSolver::distribute(const RankDecomposition& decomposition) {
  dropPreparedTimeStep();
  ranks_ = &decomposition;
  exchange_ = std::make_unique<NodalExchange>(decomposition);
  averaging_ =
      VolumetricAveraging(table_, mesh_, exchange_.get(), ranks_ ? ranks_->comm() : MPI_COMM_NULL);
  head_stabilisation_ = LiquidHeadStabilisation(table_, mesh_.numNodes(), exchange_.get());
  element_seepage_ =
      IntraElementSeepage(table_, mesh_.numElements(), mesh_.numNodes(), exchange_.get());
  setReproducibleSums(reproducible_sums_);
  outflow_limit_.distribute(exchange_.get(), decomposition.comm(), mesh_.numNodes());
  keepOwnedPoints(decomposition, points_);
  rates_.allocate(points_.count);
  evaluatePointShapes(mesh_, points_, shapes_);
  nodes_next_.rebuild(mesh_, points_, &shapes_, alwaysActiveNodes());
  nodes_next_changed_ = true;
  free_boundary_stale_ = true;
}

void ExplicitTwoPhaseSolver::setReproducibleSums(bool on) {
  // A binned sum is added to in place: the kernels write its parts directly, which is
  // race-free on Kokkos Serial only (a threaded port needs per-thread sums, merged).
  if (on && !std::is_same_v<ExecSpace, Kokkos::Serial>)
    throw std::logic_error("reproducible sums need the Kokkos Serial execution space");
  reproducible_sums_ = on;
  const int nodes = on ? mesh_.numNodes() : 0;
  for (int k = 0; k < kLowParts; ++k) {
    if (grid_lo_[k].numNodes() != nodes) grid_lo_[k].allocate(nodes);
    if (static_cast<int>(boundary_lo_[k].wet_volume_i.extent(0)) != nodes)
      boundary_lo_[k].allocate(nodes);
  }
  averaging_.compensateSums(on);
  head_stabilisation_.compensateSums(on);
  element_seepage_.compensateSums(on);
  point_borne_loads_.compensateSums(on);
}

Kokkos::View<const int*, MemSpace> ExplicitTwoPhaseSolver::alwaysActiveNodes() const {
  // A shared node is cleared, completed and solved on every rank holding it, whether or not
  // this rank's points touch it, so that all ranks hold the same value there.
  return ranks_ ? ranks_->sharedNodeView() : Kokkos::View<const int*, MemSpace>();
}

void ExplicitTwoPhaseSolver::step(Real dt) {
  if (!stage_started_) throw std::logic_error("ExplicitTwoPhaseSolver::step before beginStage");
  auto timed = [this](StepPhase phase, auto&& run) {
    PhaseTimer timer(profile_, phase);
    run();
  };
  // assembly at t^k (4.38-4.45), boundary loads; hydraulic loads on the moving boundary
  timed(StepPhase::P2G, [&] {
    mapMassesMomentaAndForces();
    applyHydraulicLoads();  // Sec. 4: free boundary, 4.51, head 4.50 / pressure loads
  });
  timed(StepPhase::NodalSolve, [&] {
    solveLiquidMomentum(dt);                  // step 1 (4.36)
    solveMixtureMomentum(dt);                 // step 2 (4.37)
    applyAccelerationBoundaryConditions(dt);  // fixities, impermeable boundaries, walls
    side_walls_.constrainAccelerations(nodes_in_use_, momentum_, dt, grid_);  // channel walls
    correctHydraulicAccelerations(dt);  // infiltration, seepage face (4.53-4.59)
  });
  timed(StepPhase::G2PVelocity, [&] { updatePointVelocities(dt); });  // step 3 (7.10, 7.11)
  timed(StepPhase::NodalSolve, [&] { updateNodalVelocities(); });     // step 4
  timed(StepPhase::G2PStrain, [&] {
    computeStrainIncrements(dt);  // step 4
    accountBoundaryFluxes(dt);    // liquid volume through each hydraulic condition
  });
  // Steps 5-7 in one pass over the points, per point in this order: updatePorosityAndVolume
  // (4.9), updateLiquidPressure (4.12 / 4.14), updateEffectiveStress (4.22, 4.5),
  // updateLiquidState (SWRC, HCC), updatePointPosition (7.13); see PointUpdates.hpp.
  timed(StepPhase::Constitutive, [&] { updatePointStates(); });
  timed(StepPhase::Relocation, [&] { relocatePoints(); });  // step 8
  if (ranks_) {  // the next step's candidate goes with the step's sums over the ranks
    timed(StepPhase::TimeStep, [&] { prepareNextTimeStep(); });
    timed(StepPhase::Relocation, [&] { completeStepOverRanks(); });
  }
  timed(StepPhase::Relocation, [&] { updateActiveNodes(); });
  if (sort_interval_ > 0 && (diagnostics_.step + 1) % sort_interval_ == 0)
    timed(StepPhase::Sort, [&] { sortPoints(); });
  time_ += dt;
  profile_.steps += 1;
  profile_.point_updates += points_.count;
  timed(StepPhase::Stability, [&] { checkStability(dt); });
}

// ------------------------------------------------------------------ the steps

void ExplicitTwoPhaseSolver::mapMassesMomentaAndForces() {
  // The grid keeps the last step's fields for output until now: clear exactly those nodes,
  // then work on the nodes of the points' current elements.
  grid_.zero(nodes_in_use_);
  if (nodes_next_changed_) std::swap(nodes_in_use_, nodes_next_);
  nodes_next_changed_ = false;
  // ---- `Conjugate Mean Stress`: the forces see the averaged mean stress (no-op unless asked)
  if (averaging_.conjugatesMeanStress()) {
    averaging_.averageMeanStresses(table_, points_, shapes_, nodes_in_use_);
    transfer_.mean_stress_shift = averaging_.meanStressShifts();
  }
  mapPointsToGrid(points_, shapes_, table_.liquidCarrying(), gravity_, transfer_, nodes_in_use_,
                  node_records_, grid_, gridCompensation());
  if (exchange_)  // several ranks: complete the sums
    sumGridAtSharedNodes(*exchange_, grid_, reproducible_sums_ ? &grid_lo_ : nullptr);
  if (reproducible_sums_) foldCompensatedGridSums(nodes_in_use_, grid_, grid_lo_);
  boundaries_.addNodalForces(time_, grid_.mass_solid_i, grid_.force_mixture_i,
                             grid_.force_liquid_i);
  side_walls_.mapResistance(points_, shapes_, nodes_in_use_, exchange_.get(), reproducible_sums_);
  computeNodalVelocities(nodes_in_use_, grid_);
}

void ExplicitTwoPhaseSolver::detectFreeBoundary() {
  // The free boundary changes only when a point changes element (Fig. 4.4).
  if (!free_boundary_stale_) return;
  if (ranks_)  // the elements holding points on any rank
    free_boundary_.detectFromActiveElements(
        globalActiveElements(ranks_->comm(), points_, mesh_.numElements()));
  else
    free_boundary_.detect(points_);
  free_boundary_stale_ = false;
  // The nodes of its sides, for the flux accounting's split into boundary and inside:
  // flags kept between detections, the old ones cleared through the old list (a detection
  // can come every step of a slide; no pass over all nodes, no allocation).
  if (static_cast<int>(free_side_nodes_.extent(0)) != mesh_.numNodes()) {
    free_side_nodes_ = Kokkos::View<unsigned char*, MemSpace>("free_side_nodes", mesh_.numNodes());
    free_side_flags_ = Kokkos::create_mirror_view(free_side_nodes_);
    Kokkos::deep_copy(free_side_flags_, 0);
    free_side_flagged_.clear();
  }
  for (const int node : free_side_flagged_) free_side_flags_(node) = 0;
  free_side_flagged_ = free_boundary_.nodes();
  for (const int node : free_side_flagged_) free_side_flags_(node) = kNodeOnFreeSide;
  for (const FreeSide& side : free_boundary_.sides())  // (no rules: every side is open)
    if (!HydraulicConditions::sealsSide(liquid_rules_, side)) {
      free_side_flags_(side.a) |= kNodeOnOpenSide;
      free_side_flags_(side.b) |= kNodeOnOpenSide;
    }
  Kokkos::deep_copy(free_side_nodes_, free_side_flags_);
  hydraulic_plan_current_ = false;
}

bool ExplicitTwoPhaseSolver::hydraulicPlanIsCurrent() const {
  // The plan depends on the free boundary, gravity and the conditions' values at time_ only:
  // with all three unchanged (constant heads and rain, between changes of the boundary) the
  // last plan is the same plan, and rebuilding it (host maps, device copies) is skipped.
  if (!hydraulic_plan_current_ || planned_gravity_ != gravity_) return false;
  return hydraulic_.valuesUnchangedAt(time_);
}

void ExplicitTwoPhaseSolver::applyHydraulicLoads() {
  // The flux weights G_i serve the conditions and the interior balance's closure, the
  // volume gradients the surface's suction.
  if (hydraulic_.empty() && !returnsLiquidMadeInside() && !holdsSuctionAtFreeSurfaces()) return;
  detectFreeBoundary();
  if (!hydraulic_.empty() && !hydraulicPlanIsCurrent()) {
    hydraulic_.plan(time_, gravity_, free_boundary_);
    hydraulic_plan_current_ = true;
    planned_gravity_ = gravity_;
    const FluxCorrectionList& corrections = hydraulic_.corrections();
    markConditionedNodes(hydraulic_.conditionedNodes());
    if (static_cast<int>(correction_locks_.extent(0)) != corrections.count())
      correction_locks_ =
          Kokkos::View<unsigned*, MemSpace>("correction_locks", corrections.count());
    const auto node = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), corrections.node);
    auto locks = Kokkos::create_mirror_view(correction_locks_);
    const NodalConstraints& constraints = boundaries_.constraints();
    // impermeable locks (the correction leaves them alone) and solid fixities (there the
    // liquid takes all of the correction: the fixity re-applied below would undo a solid share)
    for (int j = 0; j < corrections.count(); ++j)
      locks(j) = constraints.flagsOf(node(j)) &
                 (kLiquidLockedX | kLiquidLockedY | kSolidFixedX | kSolidFixedY);
    Kokkos::deep_copy(correction_locks_, locks);
    // The energy scale's loads: the largest sum of load magnitudes so far, the hydraulic
    // loads counted in the directions the solid may move (the river's pressure on a fixed
    // end of the section does no work).
    load_bound_ = std::max(load_bound_, boundaries_.totalLoadMagnitude() +
                                            freeLoadMagnitude(hydraulic_.loads(), constraints) +
                                            freeLoadMagnitude(hydraulic_.headLoads(), constraints));
    if (hydraulic_.headsThroughSoil()) checkSidesBelowHeadOutsideItsZone();
  }
  boundary_fields_.zero(nodes_in_use_);
  mapBoundaryGradients(points_, shapes_, table_.materials(), table_.liquidCarrying(), grid_,
                       boundary_fields_,  // 4.51, n_L, flux weights at t^k
                       reproducible_sums_ ? &boundary_lo_ : nullptr);
  if (exchange_)
    sumBoundaryGradientsAtSharedNodes(*exchange_, boundary_fields_,
                                      reproducible_sums_ ? &boundary_lo_ : nullptr);
  if (reproducible_sums_)
    foldCompensatedBoundarySums(nodes_in_use_, boundary_fields_, boundary_lo_);
  if (!hydraulic_.empty()) addHydraulicLoadsToGrid();  // 4.50 into 4.41 and 4.42
  if (holdsSuctionAtFreeSurfaces())                    // the air pulls on no water at suction
    holdSuctionAtFreeSurfaces(
        nodes_in_use_,
        hydraulic_.empty() ? Kokkos::View<const unsigned char*, MemSpace>() : conditioned_i_,
        boundary_fields_, grid_);
}

void ExplicitTwoPhaseSolver::addHydraulicLoadsToGrid() {
  if (!hydraulic_loads_at_points_) return argine::addHydraulicLoads(hydraulic_.loads(), grid_);
  // through the points that carry the loaded nodes (PointBorneLoads.hpp)
  point_borne_loads_.zero(nodes_in_use_);
  spreadPointBorneLoads(hydraulic_.loads(), points_, shapes_, table_.liquidCarrying(),
                        boundary_fields_, grid_, point_borne_loads_);
  if (hydraulic_.headsThroughSoil())  // the head's field over the points' volume
    spreadHeadLoadsThroughSoil(hydraulic_.headFieldThroughSoil(gravity_), points_, shapes_,
                               table_.liquidCarrying(), point_borne_loads_);
  sumPointBorneLoadsAtSharedNodes(exchange_.get(), nodes_in_use_, point_borne_loads_);
  addPointBorneLoads(point_borne_loads_, nodes_in_use_, grid_);
}

void ExplicitTwoPhaseSolver::checkSidesBelowHeadOutsideItsZone() const {
  // The head's field loads every free side below its level (HeadLoadsThroughSoil.hpp); where
  // the condition does not cover one, the load does no work only if the side is held.
  const std::size_t head = hydraulic_.throughSoilHead();
  const Real level = hydraulic_.currentValues()[head];
  std::set<std::pair<int, int>> covered;
  for (const FreeSide& side : hydraulic_.sidesUsed()[head])
    covered.insert({side.element, side.side});
  const NodalConstraints& constraints = boundaries_.constraints();
  for (const FreeSide& side : free_boundary_.sides()) {
    if (std::min(side.xa[1], side.xb[1]) >= level || covered.count({side.element, side.side}))
      continue;
    bool held = HydraulicConditions::sealsSide(head_side_rules_, side);
    for (int d = 0; d < kDim; ++d)
      if (side.normal[d] != 0)
        held = held && (constraints.flagsOf(side.a) & solidFixedBit(d)) &&
               (constraints.flagsOf(side.b) & solidFixedBit(d));
    if (held) continue;
    std::ostringstream out;
    out << "'through the soil' loads all of the soil below the level of '"
        << hydraulic_.conditions()[head].name << "' (" << level << " m), but the free side from ("
        << side.xa[0] << ", " << side.xa[1] << ") to (" << side.xb[0] << ", " << side.xb[1]
        << ") m at t = " << time_
        << " s lies below it, outside the condition's zone, and is not fixed and sealed along its "
           "normal: widen the zone to the wetted surface, or use 'at boundary points'";
    throw InputError("Stages/" + stage_name_ + "/Hydraulic Loads", out.str());
  }
}

void ExplicitTwoPhaseSolver::markConditionedNodes(Kokkos::View<const int*, MemSpace> nodes) {
  if (static_cast<int>(conditioned_i_.extent(0)) != mesh_.numNodes())
    conditioned_i_ = Kokkos::View<unsigned char*, MemSpace>("conditioned_i", mesh_.numNodes());
  Kokkos::deep_copy(conditioned_i_, 0);
  const auto flags = conditioned_i_;
  Kokkos::parallel_for(
      "mark_conditioned_nodes", Kokkos::RangePolicy<ExecSpace>(0, nodes.extent(0)),
      KOKKOS_LAMBDA(const int j) { flags(nodes(j)) = 1; });
}

std::vector<unsigned char> ExplicitTwoPhaseSolver::otherLiquidRules() const {
  using H = HydraulicConditions;
  std::vector<unsigned char> rules(mesh_.numNodes(), 0);
  const NodalConstraints& constraints = boundaries_.constraints();
  for (int i = 0; i < mesh_.numNodes(); ++i) {
    const unsigned flags = constraints.flagsOf(i);
    rules[i] =
        ((flags & kLiquidLockedX) ? H::kLockedX : 0) | ((flags & kLiquidLockedY) ? H::kLockedY : 0);
  }
  // an impermeable frictional wall (a membrane) seals its nodes along its normal, which
  // need not be axis-aligned: both bits
  const FrictionalContact& contact = boundaries_.frictionalContact();
  const auto nodes = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), contact.nodes());
  const auto flags = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), contact.flags());
  for (int j = 0; j < contact.count(); ++j)
    if (flags(j) & kContactImpermeable) rules[nodes(j)] |= H::kLockedX | H::kLockedY;
  for (const int node : boundaries_.prescribedPressureNodes())
    rules[node] |= H::kPressurePrescribed;
  return rules;
}

void ExplicitTwoPhaseSolver::correctHydraulicAccelerations(Real dt) {
  // With the liquid pressure held there is no relative flux to correct: the conditions act
  // through their loads only (the river's thrust on the slope).
  if (hydraulic_.empty() || momentum_.liquid_with_solid) return;
  argine::correctHydraulicAccelerations(hydraulic_.corrections(), boundary_fields_, dt,
                                        !momentum_.fixed_skeleton, reference_liquid_density_, grid_,
                                        correction_locks_);
  // Fixities and impermeable directions win over the correction at a node that has both:
  // the fixity's reaction takes the solid part, the impermeable lock the liquid part.
  applyAccelerationBoundaryConditions(dt);
}

void ExplicitTwoPhaseSolver::accountBoundaryFluxes(Real dt) {
  if (hydraulic_.empty()) return;
  const int conditions = static_cast<int>(hydraulic_.conditions().size());
  // Several ranks: each node counted on its owner; the sum over the ranks comes with the
  // end-of-step reduction (relocatePoints).
  if (ranks_) nodes_owned_.assignMasked(nodes_in_use_, ranks_->nodeOwnedView());
  const std::vector<Real> masses = boundaryFluxMasses(
      hydraulic_.ownership(), conditions, ranks_ ? nodes_owned_ : nodes_in_use_, free_side_nodes_,
      boundary_fields_, grid_, dt,
      returnsLiquidMadeInside() ? liquid_made_inside_i_ : Kokkos::View<Real*, MemSpace>(),
      ranks_ ? ranks_->nodeOwnedView() : Kokkos::View<const unsigned char*, MemSpace>(),
      reproducible_sums_ ? &flux_mass_sums_ : nullptr);  // merged over the ranks at the step's end
  for (int c = 0; c <= conditions + 1; ++c)
    boundary_flux_volumes_[c] = masses[c] / reference_liquid_density_;
}

void ExplicitTwoPhaseSolver::solveLiquidMomentum(Real dt) {
  argine::solveLiquidMomentum(nodes_in_use_, momentum_, dt, grid_);
}

void ExplicitTwoPhaseSolver::solveMixtureMomentum(Real dt) {
  argine::solveMixtureMomentum(nodes_in_use_, momentum_, dt, grid_);
}

void ExplicitTwoPhaseSolver::applyAccelerationBoundaryConditions(Real dt) {
  constrainAccelerations(boundaries_.constraints(), momentum_, dt, grid_);
  // The walls after the fixities: a fixity of a wall node wins there component by component.
  // Completed sums at a shared node give every rank holding it the same contact.
  constrainWallContactAccelerations(boundaries_.frictionalContact(), momentum_, dt, grid_);
}

void ExplicitTwoPhaseSolver::applyVelocityBoundaryConditions() {
  boundaries_.constraints().constrainVelocities(grid_.velocity_solid_i, grid_.velocity_liquid_i,
                                                momentum_.fixity_keeps_relative_velocity);
  boundaries_.frictionalContact().constrainVelocities(
      grid_.mass_solid_i, grid_.mass_liquid_i, grid_.velocity_solid_i, grid_.velocity_liquid_i,
      momentum_.liquid_with_solid);
  side_walls_.holdStuckNodes(nodes_in_use_, momentum_, grid_);
}

void ExplicitTwoPhaseSolver::updatePointVelocities(Real dt) {
  // APIC interpolates the grid's updated velocities, with the same conditions as the nodal
  // velocities of step 4 (a fixed node's v~ is zero, as its point neighbours then see it).
  if (carriesAffineVelocity(transfer_.scheme)) {  // APIC, TPIC
    advanceNodalVelocities(nodes_in_use_, dt, grid_);
    constrainNodalVelocities();
  }
  // XPIC: the t^k nodal velocities the PIC shares take become v* (XpicFilter.hpp), each
  // round trip's momenta completed as the remap's
  if (transfer_.scheme == TransferScheme::Xpic)
    filterNodalVelocitiesXpic(transfer_.xpic, shapes_, table_.liquidCarrying(), nodes_in_use_,
                              points_, node_records_, grid_, xpic_scratch_, gridCompensation(),
                              [&] { completeRemappedMomenta(); });
  // The G2P of the accelerations also scatters the new point momenta (the remap of step 4),
  // and sums the kinetic energies, in the same pass over the points.
  kinetic_ = updatePointVelocitiesAndMapMomenta(shapes_, table_.liquidCarrying(), nodes_in_use_, dt,
                                                transfer_, points_, node_records_, grid_,
                                                gridCompensation());
  completeRemappedMomenta();  // (kinetic_: end of step)
  if (reproducible_sums_) {
    // the run totals too: the kernel's energies again, compensated (same terms)
    kinetic_pairs_ = compensatedKineticEnergies(
        points_.element, points_.material, table_.liquidCarrying(), points_.mass_solid,
        points_.mass_liquid, points_.velocity_solid, points_.velocity_liquid);
    kinetic_.solid = kinetic_pairs_.solid.value();
    kinetic_.liquid = kinetic_pairs_.liquid.value();
  }
}

void ExplicitTwoPhaseSolver::completeRemappedMomenta() {
  if (exchange_)
    sumMomentaAtSharedNodes(*exchange_, grid_, reproducible_sums_ ? &grid_lo_ : nullptr);
  if (reproducible_sums_) foldCompensatedMomenta(nodes_in_use_, grid_, grid_lo_);
}

void ExplicitTwoPhaseSolver::updateNodalVelocities() {
  computeNodalVelocities(nodes_in_use_, grid_);
  constrainNodalVelocities();
}

void ExplicitTwoPhaseSolver::constrainNodalVelocities() {
  if (!hydraulic_.empty() &&
      !momentum_
           .liquid_with_solid) {  // the relative flux of the mass balance is the prescribed one
    // constrained first, as the accelerations were: the correction measures the flux of the
    // constrained velocities (a lock across the face normal would change it afterwards)
    applyVelocityBoundaryConditions();
    correctHydraulicVelocities(hydraulic_.corrections(), boundary_fields_,
                               !momentum_.fixed_skeleton, reference_liquid_density_, grid_,
                               correction_locks_);
  }
  applyVelocityBoundaryConditions();
  if (momentum_.liquid_with_solid) moveLiquidWithSolid(nodes_in_use_, grid_);
}

void ExplicitTwoPhaseSolver::computeStrainIncrements(Real dt) {
  interpolateVelocityGradients(
      points_, shapes_, table_.liquidCarrying(), nodes_in_use_, grid_, node_records_, dt, rates_,
      hydraulic_.empty() ? Kokkos::View<const unsigned char*, MemSpace>() : conditioned_i_,
      transfer_.scheme);
  // ---- `Interior Liquid Balance: conservative`: what the point balance makes at the nodes
  // inside the body, given back by the points around them (InteriorLiquidBalance.hpp).
  if (returnsLiquidMadeInside()) {
    liquidMadeAtClosedNodes(
        nodes_in_use_, free_side_nodes_,
        hydraulic_.empty() ? Kokkos::View<const unsigned char*, MemSpace>() : conditioned_i_,
        boundary_fields_, grid_, dt, liquid_made_inside_i_);
    returnLiquidMadeInside(table_, points_, shapes_, boundary_fields_, liquid_made_inside_i_,
                           rates_);
  }
  // ---- Locking mitigation: smoothed d eps_vol (no-op unless a material asks for it).
  averaging_.averageStrainIncrements(table_, points_, shapes_, nodes_in_use_, rates_);
  // ---- Against the Tri3 pressure checkerboard: a conservative head exchange (no-op unless a
  // material asks for it; a held p_L takes no flux).
  if (!momentum_.liquid_with_solid)
    head_stabilisation_.apply(table_, points_, shapes_, nodes_in_use_, rates_, dt, gravity_);
  // ---- The Darcy flow between the points of one element, which the grid cannot see
  // (IntraElementSeepage.hpp; no-op unless a material asks for it).
  if (!momentum_.liquid_with_solid)
    element_seepage_.apply(table_, points_, shapes_, nodes_in_use_, rates_, dt, gravity_);
  // No point gives away more than its mobile liquid (LiquidOutflowLimit.hpp); a no-op
  // unless a point near residual saturation is asked for more.
  outflow_limited_ = outflow_limit_.apply(table_, points_, shapes_, rates_).limited_points;
}

void ExplicitTwoPhaseSolver::updatePointStates() {
  averaging_.rememberPressures(points_);  // ---- Locking mitigation (no-op unless asked)
  if (air_path_.enabled()) {              // ---- Air-filled cracks open only where air reaches them
    detectFreeBoundary();
    air_path_.update(free_boundary_, points_, ranks_ ? ranks_->comm() : MPI_COMM_NULL);
  }
  const bool held = momentum_.liquid_with_solid;
  totals_ = argine::updatePointStates(table_, rates_, points_, held, air_path_.reachesElement(),
                                      !(held && held_liquid_state_renewed_));
  held_liquid_state_renewed_ = held;
  if (reproducible_sums_) {  // the liquid mass of the step, compensated (same terms)
    liquid_mass_pair_ = compensatedSum(points_.mass_liquid);
    totals_.liquid_mass = liquid_mass_pair_.value();
  }
  // ---- Locking mitigation: smoothed d p_L at saturated points (no-op unless asked).
  averaging_.averagePressureIncrements(table_, points_, shapes_, nodes_in_use_);
}

void ExplicitTwoPhaseSolver::relocatePoints() {
  relocation_ = relocateAndEvaluateShapes(mesh_, locator_, element_maps_, points_, shapes_);
}

const TimeStepChoice& ExplicitTwoPhaseSolver::localTimeStep() {
  return points_.count > 0 ? time_step_.next(points_, table_) : time_step_.nextWithoutPoints();
}

void ExplicitTwoPhaseSolver::prepareNextTimeStep() {
  // What chooseTimeStep() would do before the next step, done now on the relocated points so
  // that its minimum over the ranks travels with the end-of-step reduction. The points are
  // the same wherever they live (migration moves them unchanged), so the minimum is too.
  state_before_candidate_ = time_step_.state();
  candidate_.ready = true;
  try {
    candidate_.choice = localTimeStep();
  } catch (const RunError&) {
    // No usable step here: chooseTimeStep() evaluates again on every rank and reports it.
    time_step_.restore(state_before_candidate_);
    candidate_.ready = false;
  }
}

void ExplicitTwoPhaseSolver::completeStepOverRanks() {
  RelocationCounts& counts = relocation_;
  // The step's sums over the ranks in one reduction (the stability check reads them), with
  // the next time step...
  EndOfStepSums sums;
  sums.kinetic_solid = kinetic_.solid;
  sums.kinetic_liquid = kinetic_.liquid;
  sums.non_finite_velocity = kinetic_.non_finite_points;
  sums.liquid_mass = totals_.liquid_mass;
  sums.non_finite_state = totals_.non_finite_points;
  sums.lost = counts.lost;
  sums.changed_element = counts.changed_element;
  sums.emigrants = countEmigrants(*ranks_, points_);
  sumOverRanks(ranks_->comm(), sums, boundary_flux_volumes_, &candidate_, reduction_scratch_);
  if (candidate_.ready) {
    prepared_time_step_ = true;
  } else {
    time_step_.restore(state_before_candidate_);  // the next chooseTimeStep() does it again
  }
  if (reproducible_sums_) {  // the totals again, from the ranks' binned sums
    std::vector<CompensatedReal>& totals = totals_sums_;  // a member: no allocation per step
    totals.assign({kinetic_pairs_.solid, kinetic_pairs_.liquid, liquid_mass_pair_});
    if (!hydraulic_.empty())
      totals.insert(totals.end(), flux_mass_sums_.begin(), flux_mass_sums_.end());
    sumCompensatedOverRanks(ranks_->comm(), totals, reduction_scratch_);
    sums.kinetic_solid = totals[0].value();
    sums.kinetic_liquid = totals[1].value();
    sums.liquid_mass = totals[2].value();
    for (std::size_t c = 3; c < totals.size(); ++c)
      boundary_flux_volumes_[c - 3] = totals[c].value() / reference_liquid_density_;
  }
  kinetic_.solid = sums.kinetic_solid;
  kinetic_.liquid = sums.kinetic_liquid;
  kinetic_.non_finite_points = static_cast<int>(sums.non_finite_velocity);
  totals_.liquid_mass = sums.liquid_mass;
  totals_.non_finite_points = static_cast<int>(sums.non_finite_state);
  counts.lost = static_cast<int>(sums.lost);
  counts.changed_element = static_cast<int>(sums.changed_element);
  // ... then the points that entered another rank's element move there.
  const MigrationCounts moved =
      exchangePoints(*ranks_, points_, static_cast<long long>(sums.emigrants));
  migrated_points_ += moved.total;
  if (moved.sent > 0 || moved.received > 0) {
    relocateAndEvaluateShapes(mesh_, locator_, element_maps_, points_, shapes_);
    pointsReordered();
  }
}

void ExplicitTwoPhaseSolver::updateActiveNodes() {
  diagnostics_.lost_points = relocation_.lost;
  // No point changed element (the common case): the active nodes stay nodes_in_use_.
  if (relocation_.changed_element > 0) {
    nodes_next_.rebuild(mesh_, points_, &shapes_, alwaysActiveNodes());
    nodes_next_changed_ = true;
    free_boundary_stale_ = true;
  }
}

void ExplicitTwoPhaseSolver::pointsReordered() {
  time_step_.pointsReordered(points_);
  // The prepared step's point: an index on the rank holding it now.
  if (prepared_time_step_ && candidate_.choice.point_id >= 0)
    candidate_.choice.point = pointIndexOfId(points_, candidate_.choice.point_id);
}

void ExplicitTwoPhaseSolver::dropPreparedTimeStep() {
  if (!prepared_time_step_) return;
  time_step_.restore(state_before_candidate_);
  prepared_time_step_ = false;
}

void ExplicitTwoPhaseSolver::sortPoints() {
  // After the relocation, by the elements of t^{k+1}. Relocating the sorted points again
  // (one cheap pass every sortInterval() steps) gives each point exactly the element, local
  // coordinates and shape functions it had (see relocateAndEvaluateShapes); the active
  // nodes are the same set.
  sortPointsByElement(points_);
  relocateAndEvaluateShapes(mesh_, locator_, element_maps_, points_, shapes_);
  pointsReordered();
  profile_.sorts += 1;
}

void ExplicitTwoPhaseSolver::countInflowEnergy() {
  // The liquid that entered through each condition in this step (over the ranks already)
  // with the most energy per kg it can bring (StabilityCheck.hpp: inflowEnergyPerMass).
  const auto& conditions = hydraulic_.conditions();
  for (std::size_t c = 0; c < conditions.size(); ++c) {
    const Real mass = boundary_flux_volumes_[c] * reference_liquid_density_;
    if (!(mass > 0)) continue;
    const HydraulicCondition& h = conditions[c];
    const Real above = h.above == AboveLevel::ConstantPressure ? h.pressure_above : 0;
    inflow_energy_ +=
        mass * inflowEnergyPerMass(h.kind, hydraulic_.largestCurrentValue(c), above,
                                   h.liquid_density, gravity_, mesh_top_, mesh_bottom_);
  }
}

void ExplicitTwoPhaseSolver::checkStability(Real dt) {
  if (!hydraulic_.empty()) countInflowEnergy();
  PointTotals totals = totals_;
  totals.kinetic_energy_solid = kinetic_.solid;
  totals.kinetic_energy_liquid = kinetic_.liquid;
  totals.non_finite_points += kinetic_.non_finite_points;
  diagnostics_.step += 1;
  diagnostics_.time = time_;
  diagnostics_.time_step = dt;
  diagnostics_.kinetic_energy_solid = totals.kinetic_energy_solid;
  diagnostics_.kinetic_energy_liquid = totals.kinetic_energy_liquid;
  diagnostics_.liquid_mass = totals.liquid_mass;
  diagnostics_.active_nodes = nodes_in_use_.count();
  diagnostics_.outflow_limited_points = outflow_limited_;
  diagnostics_.time_step_choice = ranks_ ? global_choice_ : time_step_.last();

  auto fail = [&](const std::string& what) {
    std::ostringstream out;
    out << "unstable at t = " << time_ << " s (step " << diagnostics_.step << ", dt = " << dt
        << " s, stage " << stage_name_ << "): " << what;
    throw RunError(out.str());
  };
  if (totals.non_finite_points > 0) {
    const int point = firstNonFinitePoint(points_);
    std::ostringstream out;
    out << totals.non_finite_points
        << " point(s) with non-finite values or collapsed volume, first "
        << (point >= 0 ? describePoint(points_, point, true) : "on another MPI rank");
    fail(out.str());
  }
  // A stable stage cannot turn more than the energy scale into motion (energyScale): above
  // it the run made energy, i.e. it is unstable.
  const Real kinetic = totals.kinetic_energy_solid + totals.kinetic_energy_liquid;
  const Real scale = stageEnergyScale();
  // The allowance is round-off: a stage whose only energy is its initial motion keeps it
  // exactly only in exact arithmetic (APIC's v_p = sum N v_i of a uniform field differs from
  // v_p in the last bits), and the sums over the points carry ~n eps of relative error.
  constexpr Real kRoundOff = 1e-9;
  const Real bound = energy_growth_limit_ * scale * (1 + kRoundOff);
  if (kinetic > bound && kinetic > 0) {
    std::ostringstream out;
    out << "kinetic energy " << kinetic << " J/m exceeds " << energy_growth_limit_
        << " x the stage's energy scale " << scale << " J/m (at the stage start: potential "
        << stage_energies_.potential << ", stored " << stage_energies_.stored << ", kinetic "
        << stage_energies_.kinetic << " J/m; loads " << load_bound_ << " N/m x mesh extent "
        << mesh_size_ << " m; liquid inflow " << inflow_energy_ << " J/m); most energetic: "
        << (points_.count > 0 ? describePoint(points_, mostEnergeticPoint(points_), false)
                              : "on another MPI rank");
    fail(out.str());
  }
}

// ------------------------------------------------------------------ output

std::vector<std::string> ExplicitTwoPhaseSolver::nodalFieldNames() {
  return {"mass_solid",       "mass_liquid",       "velocity_solid_x",
          "velocity_solid_y", "velocity_liquid_x", "velocity_liquid_y"};
}

std::vector<NamedNodalField> ExplicitTwoPhaseSolver::nodalFields() {
  const auto names = nodalFieldNames();
  const int nodes = grid_.numNodes();
  if (output_.size() != names.size()) {
    output_.clear();
    for (const auto& name : names) output_.emplace_back("output_" + name, nodes);
  }
  Kokkos::deep_copy(output_[0], grid_.mass_solid_i);
  Kokkos::deep_copy(output_[1], grid_.mass_liquid_i);
  Kokkos::deep_copy(output_[2], Kokkos::subview(grid_.velocity_solid_i, Kokkos::ALL, 0));
  Kokkos::deep_copy(output_[3], Kokkos::subview(grid_.velocity_solid_i, Kokkos::ALL, 1));
  Kokkos::deep_copy(output_[4], Kokkos::subview(grid_.velocity_liquid_i, Kokkos::ALL, 0));
  Kokkos::deep_copy(output_[5], Kokkos::subview(grid_.velocity_liquid_i, Kokkos::ALL, 1));
  std::vector<NamedNodalField> fields;
  for (std::size_t k = 0; k < names.size(); ++k) fields.push_back({names[k], output_[k]});
  return fields;
}

}  // namespace argine
