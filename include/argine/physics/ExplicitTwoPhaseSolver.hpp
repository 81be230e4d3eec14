#pragma once
/// @file ExplicitTwoPhaseSolver.hpp
/// The explicit "2Phase with suction" single-point MPM step (thesis Ch. 4 Sec. 3.3), with
/// Euler-Cromer time integration (7.10-7.13). One set of material points carries solid and
/// liquid; the liquid moves relative to the solid. `step(dt)` reads as the algorithm:
///
///   mapMassesMomentaAndForces   P2G at t^k: masses 4.38-4.40, drag 4.45, forces 4.41-4.44
///   applyHydraulicLoads         moving boundary (Sec. 4): detectFreeBoundary (Fig. 4.4, when
///                               a point changed element), normals 4.51, head (4.50) and
///                               pressure loads into f_L^ext and f^ext
///   solveLiquidMomentum         step 1: a_L from 4.36
///   solveMixtureMomentum        step 2: a_S from 4.37
///   applyAccelerationBoundaryConditions   fixities, impermeable boundaries, frictional walls
///                               (Coulomb contact of the solid, WallContact.hpp)
///   correctHydraulicAccelerations   infiltration / seepage face predictor-corrector
///                               (4.53-4.59)
///   updatePointVelocities       step 3: v_p += dt sum N a (7.10, 7.11; FLIP) or, with APIC,
///                               v_p and C_p from the grid's v + dt a (conditions imposed),
///                               and the remap of the new point momenta to the nodes, in one
///                               pass
///   updateNodalVelocities       step 4: nodal v^{k+1} = momentum / mass, velocity BCs (the
///                               walls' contact in velocity form too), the infiltration /
///                               seepage corrections re-imposed
///   computeStrainIncrements     step 4: d eps, spin, div v_L, advective term at the points;
///                               volumetric averaging of d eps if a material asks for it;
///                               the donor limit of the outflow at dry points
///                               (LiquidOutflowLimit.hpp)
///   accountBoundaryFluxes       liquid volume through each hydraulic condition
///   updatePointStates           (with air-filled cracks: where air reaches, AirPath.hpp)
///                               steps 5-7 in one pass over the points, per point:
///     updatePorosityAndVolume   step 6: 4.9 (first: the mass balance needs n V)
///     updateLiquidPressure      step 5: mass balance 4.12 (or 4.14), conservative form
///     updateEffectiveStress     step 5: sigma' (4.22), Bishop chi = S_L (4.5)
///     updateLiquidState         step 6: S_L (SWRC), k (HCC)
///     updatePointPosition       step 7: x += dt sum N v_S^{k+1} (7.13)
///   (averaging of d p_L at saturated points if a material asks for it, VolumetricAveraging)
///   relocatePoints              step 8: grid discarded, points re-located for t^{k+1}
///   sortPoints                  every sortInterval() steps (if set): points by element
///   checkStability              non-finite values or runaway kinetic energy -> RunError
///
/// Cost: every loop runs over the points or over the ACTIVE nodes (nodes of elements that
/// hold points); the background mesh is touched only by an O(nodes) byte scan that lists the
/// active nodes once per step. Empty elements cost nothing else. With setSortInterval(N)
/// the points are sorted by element every N steps (Kokkos::BinSort, sortPointsByElement),
/// so the P2G/G2P of neighbouring points touch neighbouring nodes; a point's INDEX may then
/// change at any step: follow a point by its `id`. profile() says where the time went.
///
/// Typical use (the Simulation loop):
///   initialisePointState(deck.materials, points);          // physics/PointInitialisation
///   ExplicitTwoPhaseSolver solver(mesh, points, deck.materials);
///   solver.setSortInterval(ExplicitTwoPhaseSolver::kRecommendedSortInterval);
///   for (const StageSpec& stage : deck.stages) {
///     solver.beginStage(stage);
///     const Real end = solver.time() + stage.duration;
///     while (solver.time() < end) {
///       const Real dt = std::min(solver.chooseTimeStep().time_step, end - solver.time());
///       solver.step(dt);                                      // may throw RunError
///       // solver.diagnostics(), solver.nodalFields() for output
///     }
///   }
///   std::printf("%s", solver.profile().describe().c_str());   // where the time went

#include <memory>
#include <string>
#include <vector>

#include "argine/boundary/BoundaryConditions.hpp"
#include "argine/boundary/FreeBoundary.hpp"
#include "argine/boundary/HydraulicConditions.hpp"
#include "argine/core/Types.hpp"
#include "argine/mesh/PointLocator.hpp"
#include "argine/parallel/NodalExchange.hpp"
#include "argine/physics/AirPath.hpp"
#include "argine/physics/DistributedStep.hpp"
#include "argine/physics/HydraulicBoundaryStep.hpp"
#include "argine/physics/IntraElementSeepage.hpp"
#include "argine/physics/LiquidHeadStabilisation.hpp"
#include "argine/physics/LiquidOutflowLimit.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/physics/MomentumBalance.hpp"
#include "argine/physics/PointBorneLoads.hpp"
#include "argine/physics/SideWallFriction.hpp"
#include "argine/physics/StabilityCheck.hpp"
#include "argine/physics/StepProfile.hpp"
#include "argine/physics/TimeStepControl.hpp"
#include "argine/physics/VolumetricAveraging.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/AffineElementMaps.hpp"
#include "argine/transfer/CompensatedSum.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/NodeRecords.hpp"
#include "argine/transfer/PointRates.hpp"
#include "argine/transfer/PointShapes.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"
#include "argine/transfer/XpicFilter.hpp"

namespace argine {

struct MaterialPoints;
struct MaterialSpec;
struct Mesh;
class RankDecomposition;
struct StageSpec;

/// What the last step did, for logs, probes and output.
struct StepDiagnostics {
  long step = 0;                    ///< steps taken since the solver was made
  Real time = 0;                    ///< time after the last step (s)
  Real time_step = 0;               ///< dt of the last step (s)
  Real kinetic_energy_solid = 0;    ///< sum 1/2 M_S |v_S|^2 (J per m thickness)
  Real kinetic_energy_liquid = 0;   ///< sum 1/2 M_L |v_L|^2 (J per m thickness)
  Real liquid_mass = 0;             ///< sum M_L (kg per m thickness)
  int lost_points = 0;              ///< points that left the mesh (element -1)
  int active_nodes = 0;             ///< nodes the last step computed on
  int outflow_limited_points = 0;   ///< points whose outflow the donor limit capped
  TimeStepChoice time_step_choice;  ///< how the last automatic/fixed step was chosen
};

/// A nodal field for output: name and one value per mesh node (zero off the active nodes).
struct NamedNodalField {
  std::string name;                            ///< e.g. "velocity_solid_x"
  Kokkos::View<const Real*, MemSpace> values;  ///< one value per mesh node
};

class ExplicitTwoPhaseSolver {
 public:
  /// Keeps references to `mesh` and `points` (owned by the caller, who must keep them alive).
  /// The points must be seeded (element, local, volume) and initialised
  /// (initialisePointState). Builds the point locator and evaluates the shape functions.
  ExplicitTwoPhaseSolver(const Mesh& mesh, MaterialPoints& points,
                         const std::vector<MaterialSpec>& materials);

  /// Replaces the material parameters (a stage that changes e.g. the cohesion); the point
  /// state is kept, except S_L and k, re-evaluated from the new curves at each point's p_L.
  /// The phase model of a material must not change (points keep their liquid or lack of it).
  /// The next chooseTimeStep() evaluates the criteria again.
  void setMaterials(const std::vector<MaterialSpec>& materials);

  /// Starts a stage: solver kind (Explicit, QuasiStatic or FixedSkeleton; InputError for
  /// ImplicitSeepage), gravity, local damping, mass scaling, time-step control, boundary
  /// conditions (InputError "Stages/<stage>/Boundary Conditions/<name>" for a missing set),
  /// displacement reset. A fixed-skeleton stage sets the solid velocities to zero.
  void beginStage(const StageSpec& stage);

  /// The step to take next: automatic (safety factor x minimum critical step, with the
  /// governing criterion and point) or the stage's fixed step.
  const TimeStepChoice& chooseTimeStep();

  /// Advances the solution by dt (Sec. 3.3). Throws RunError (time, step, point, quantity)
  /// when the result is not finite or the kinetic energy runs away; the points then hold
  /// the failed state, so keep the last good output.
  void step(Real dt);

  /// Current time (s); starts at 0 and is not reset by beginStage.
  Real time() const { return time_; }
  /// Sets the current time (restarts).
  void setTime(Real time) { time_ = time; }
  /// Diagnostics of the last step.
  const StepDiagnostics& diagnostics() const { return diagnostics_; }
  /// The nodal fields of the last step (t^k masses; velocities v^{k+1} after the remap).
  const GridFields& grid() const { return grid_; }
  /// Output copies: mass_solid, mass_liquid, velocity_solid_x/_y, velocity_liquid_x/_y.
  std::vector<NamedNodalField> nodalFields();
  /// Names of nodalFields(), in order, for declaring output variables.
  static std::vector<std::string> nodalFieldNames();
  /// The current stage's resolved boundary conditions.
  const StageBoundaryConditions& boundaryConditions() const { return boundaries_; }

  // ---- hydraulic conditions on the moving boundary (Sec. 4.1-4.3)
  /// The free boundary of the last step (detected only while the stage has hydraulic
  /// conditions).
  const FreeBoundary& freeBoundary() const { return free_boundary_; }
  /// The current stage's hydraulic conditions (last step's plan).
  const HydraulicConditions& hydraulicConditions() const { return hydraulic_; }
  /// Liquid volume (m^3 per m thickness, mass / reference rho_L) that ENTERED the soil in
  /// the last step through each hydraulic condition, in hydraulicConditions() order; the
  /// entry after them is the net inflow through all nodes (= the storage change), the last
  /// the part of it at the nodes on no side of the free boundary (made inside the body).
  const std::vector<Real>& boundaryFluxVolumes() const { return boundary_flux_volumes_; }
  /// rho_L converting liquid masses to volumes: that of the first liquid-carrying material.
  Real referenceLiquidDensity() const { return reference_liquid_density_; }
  /// The energy scale (J/m) of the instability bound (StabilityCheck.hpp: energyScale) as it
  /// stands after the last step: the points' energy at the stage start, plus the largest
  /// load of the stage so far times the mesh's extent, plus the energy of the liquid that
  /// entered so far.
  Real stageEnergyScale() const {
    return energyScale(stage_energies_, load_bound_, mesh_size_, inflow_energy_);
  }
  /// The nodal fields of the hydraulic conditions of the last step (4.51, n_L, G_i).
  const BoundaryGradientFields& boundaryGradients() const { return boundary_fields_; }

  /// The kinetic energy may not exceed this factor times stageEnergyScale(). Default 1: the
  /// scale bounds what a stable stage can turn into motion (StabilityCheck.hpp, energyScale),
  /// so only a run that makes energy gets there.
  void setEnergyGrowthLimit(Real factor) { energy_growth_limit_ = factor; }

  /// Sort the points by element every `steps` steps (0: never, the default, so that a
  /// caller's point indices stay valid). Sorting permutes the points (indices change, ids
  /// stay) and changes results only by the order of the P2G sums (round-off). A run that
  /// follows points by id (output, probes) should use kRecommendedSortInterval.
  void setSortInterval(int steps) { sort_interval_ = steps > 0 ? steps : 0; }
  /// Steps between two sorts of the points (0: never).
  int sortInterval() const { return sort_interval_; }

  /// Reproducible sums (deck `Parallel: {Reproducible Sums: true}`, transfer/CompensatedSum.hpp):
  /// every node sum that feeds the state (P2G, momentum remap, hydraulic boundary gradients,
  /// volumetric averaging, head stabilisation) and the run totals (energies, liquid mass,
  /// boundary fluxes) are binned and rounded once complete, so the results do not
  /// depend on the number of MPI ranks or on the order of the points (except with a
  /// probability of order 1e-14 per sum; the outflow limit keeps plain sums). Costs about
  /// 2x in those kernels. Off by default.
  void setReproducibleSums(bool on);
  bool reproducibleSums() const { return reproducible_sums_; }
  /// Rarely enough that sorting costs ~1 % of the steps, often enough that points mixed by
  /// large deformations are ordered again quickly (see verification/benchmark).
  static constexpr int kRecommendedSortInterval = 50;

  // ---- several MPI ranks (doc/parallel.md; the communication is physics/DistributedStep.hpp)
  /// Runs the steps on the ranks of `decomposition` (kept by reference; it must outlive the
  /// solver): keeps only the points of this rank's elements (every rank seeded the same
  /// points), then each step completes the nodal sums at the shared nodes, reduces the
  /// sums and the time step over the ranks and migrates the points that cross into another
  /// rank's elements. Collective: every rank calls the same solver functions in the same
  /// order. Call before the first beginStage (again after an implicit stage that gathered
  /// the points).
  void distribute(const RankDecomposition& decomposition);
  /// The decomposition (nullptr on one rank without distribute()).
  const RankDecomposition* decomposition() const { return ranks_; }
  /// Points moved between ranks since distribute() (sum over all ranks and steps).
  long long migratedPoints() const { return migrated_points_; }
  /// This rank's nodal exchange traffic (nullptr without distribute()).
  const ExchangeTraffic* exchangeTraffic() const {
    return exchange_ ? &exchange_->traffic() : nullptr;
  }

  /// Wall time per phase of the steps (and chooseTimeStep calls) since construction or the
  /// last resetProfile(), with the number of steps and point updates.
  const StepProfile& profile() const { return profile_; }
  /// Clears profile() (e.g. after warm-up steps).
  void resetProfile() { profile_.reset(); }

  // ---- checkpoint / restart (simulation/Checkpoint.hpp; ExplicitSolverResume.cpp)
  /// What the solver carries from step to step besides the points and what beginStage()
  /// derives from the deck: the rest (shape functions, active nodes, free boundary, grid) is
  /// a function of the points and is derived again by resume().
  struct ResumeState {
    Real time = 0;
    StepDiagnostics diagnostics;   ///< its step count drives the sort interval
    PointEnergies stage_energies;  ///< of the energy scale: the points at the stage start
    Real load_bound = 0;           ///< of the energy scale: largest load so far (N/m)
    Real inflow_energy = 0;        ///< of the energy scale: brought by entering liquid (J/m)
    bool stage_started = false;    ///< false: checkpoint at a stage boundary
    TimeStepControl::State time_step;
  };
  ResumeState resumeState() const;
  /// Continues from `state` once the points hold the checkpoint's values (same count and
  /// order) and, when state.stage_started, beginStage() ran for the checkpoint's stage. Gives
  /// the points the shape functions, active nodes and free boundary the uninterrupted run
  /// holds (relocation from unchanged positions is exact, see relocateAndEvaluateShapes).
  void resume(const ResumeState& state);

 private:
  // The steps of Sec. 3.3, in order.
  void mapMassesMomentaAndForces();
  void applyHydraulicLoads();
  /// The planned loads into f^ext and f_L^ext: at their nodes, or through the points
  /// (`Hydraulic Loads`, PointBorneLoads.hpp).
  void addHydraulicLoadsToGrid();
  /// `Hydraulic Loads: through the soil`: InputError at a free side below the head's level
  /// that its condition does not cover and that is not fixed and sealed along its normal.
  void checkSidesBelowHeadOutsideItsZone() const;
  void detectFreeBoundary();
  bool hydraulicPlanIsCurrent() const;
  void solveLiquidMomentum(Real dt);
  void solveMixtureMomentum(Real dt);
  void applyAccelerationBoundaryConditions(Real dt);
  void correctHydraulicAccelerations(Real dt);
  void applyVelocityBoundaryConditions();  // of updateNodalVelocities
  void updatePointVelocities(Real dt);
  void updateNodalVelocities();
  /// The remapped momenta summed over the ranks and folded (reproducible sums).
  void completeRemappedMomenta();
  void constrainNodalVelocities();  // velocity conditions and hydraulic corrections
  void computeStrainIncrements(Real dt);
  void accountBoundaryFluxes(Real dt);
  void updatePointStates();
  void relocatePoints();
  const TimeStepChoice& localTimeStep();  // several ranks: this rank's next() call
  void prepareNextTimeStep();             // several ranks: this rank's candidate for the next step
  void completeStepOverRanks();  // several ranks: the step's sums, the next step, migration
  void updateActiveNodes();
  void sortPoints();
  void checkStability(Real dt);
  /// Adds the energy of this step's liquid inflow to the energy scale (inflow_energy_).
  void countInflowEnergy();
  /// The points were permuted or moved between ranks: choices follow their point by id.
  void pointsReordered();
  /// Forgets a step prepared at the end of the last step (the state it came from changed).
  void dropPreparedTimeStep();

  const Mesh& mesh_;
  MaterialPoints& points_;
  MaterialTable table_;
  PointLocator locator_;
  AffineElementMaps element_maps_;  ///< cheap relocation in affine elements
  PointShapes shapes_;
  PointRates rates_;
  GridFields grid_;
  NodeRecords node_records_;  ///< scratch of the transfer kernels (packed nodal rows)
  XpicScratch xpic_scratch_;  ///< XPIC's filtered velocities and the points' own
  bool reproducible_sums_ = false;
  LowParts<GridFields> grid_lo_;                  ///< reproducible sums: low parts of grid_'s
  LowParts<BoundaryGradientFields> boundary_lo_;  ///< ... and of boundary_fields_' sums
  const LowParts<GridFields>* gridCompensation() const {
    return reproducible_sums_ ? &grid_lo_ : nullptr;
  }
  // Reproducible sums: this rank's run totals as binned sums, merged over the ranks at the
  // end of the step (sumCompensatedOverRanks).
  CompensatedKinetic kinetic_pairs_;
  CompensatedReal liquid_mass_pair_;
  std::vector<CompensatedReal> flux_mass_sums_;  ///< per condition, all nodes, inside the body
  std::vector<CompensatedReal> totals_sums_;     ///< the sums merged at the end of a step
  ActiveNodes nodes_in_use_;        ///< nodes whose grid fields hold the current/last step
  ActiveNodes nodes_next_;          ///< nodes of the points' current elements (next step)
  bool nodes_next_changed_ = true;  ///< nodes_next_ differs from nodes_in_use_ (else unused)
  StageBoundaryConditions boundaries_;
  SideWallFriction side_walls_;  ///< the walls of a quasi-2D channel (stage `side walls`)
  FreeBoundary free_boundary_;
  AirPath air_path_;  ///< where an air-filled crack may open (materials with such cracks)
  HydraulicConditions hydraulic_;
  BoundaryGradientFields boundary_fields_;
  /// `Hydraulic Loads: at boundary points` (StageSpec::hydraulic_loads_at_points) and its
  /// nodal work fields.
  bool hydraulic_loads_at_points_ = false;
  PointBorneLoadFields point_borne_loads_;
  /// Per entry of hydraulic_.corrections(): the node's impermeable-lock and solid-fixity bits
  /// (the flux correction acts in the unlocked directions only, and through the liquid alone
  /// where the solid is fixed), refreshed with each plan.
  Kokkos::View<unsigned*, MemSpace> correction_locks_;
  /// 1 at the nodes the current plan's hydraulic conditions act on (loads, corrections; not
  /// the atmosphere's): a point touching one is not alone for the liquid
  /// (interpolateVelocityGradients).
  Kokkos::View<unsigned char*, MemSpace> conditioned_i_;
  void markConditionedNodes(Kokkos::View<const int*, MemSpace> nodes);
  /// What the stage's impermeable, frictional-wall and liquid-pressure conditions say about
  /// the liquid at each node, for the atmosphere (HydraulicConditions::setOtherLiquidRules).
  std::vector<unsigned char> otherLiquidRules() const;
  bool free_boundary_stale_ = true;      ///< a point changed element since the last detection
  bool hydraulic_plan_current_ = false;  ///< hydraulic_ planned on the current free boundary
  Real planned_gravity_ = 0;             ///< the gravity of that plan
  std::vector<Real> boundary_flux_volumes_;
  /// `Interior Liquid Balance: conservative` (StageSpec::interior_liquid_conservative) and
  /// the mass the points give back at each closed node this step (InteriorLiquidBalance.hpp).
  bool interior_liquid_conservative_ = false;
  Kokkos::View<Real*, MemSpace> liquid_made_inside_i_;
  /// otherLiquidRules() of the stage when it closes nodes (which free sides are sealed).
  std::vector<unsigned char> liquid_rules_;
  /// otherLiquidRules() of a stage whose head loads through the soil (the sealed sides its
  /// check accepts), made once a stage, not at every plan.
  std::vector<unsigned char> head_side_rules_;
  bool returnsLiquidMadeInside() const {
    return interior_liquid_conservative_ && !momentum_.liquid_with_solid;
  }
  /// `Free Surface Liquid Pressure: suction held` in this stage (FreeSurfaceSuction.hpp):
  /// whether the boundary pass maps the volume gradients and nodal pressures it reads.
  bool holdsSuctionAtFreeSurfaces() const { return boundary_fields_.with_surface_pressure; }
  Kokkos::View<unsigned char*, MemSpace> free_side_nodes_;  ///< FreeSideNodeBits of each node
  Kokkos::View<unsigned char*, MemSpace>::HostMirror free_side_flags_;  ///< its host copy
  std::vector<int> free_side_flagged_;  ///< the nodes flagged in it now
  Real reference_liquid_density_ = 1000;
  bool carries_liquid_ = false;    ///< some material carries liquid
  VolumetricAveraging averaging_;  ///< anti-locking averaging (materials' Locking Mitigation)
  LiquidHeadStabilisation head_stabilisation_;  ///< against the Tri3 p_L checkerboard
  IntraElementSeepage element_seepage_;         ///< p_L differences inside an element (P11)
  LiquidOutflowLimit outflow_limit_;            ///< donor limit of the mass balance at dry points
  int outflow_limited_ = 0;                     ///< points it capped in this step
  /// In a stage with `Liquid Pressure: held`: S_L and k have been renewed from the held p_L
  /// (after the stage's first step). No step of such a stage changes an unsaturated point's
  /// p_L, so the retention and conductivity curves (two to four pow calls a point) would
  /// give the same values again; beginStage, setMaterials and a restart clear it.
  bool held_liquid_state_renewed_ = false;
  TimeStepControl time_step_;
  MomentumSettings momentum_;
  TransferSettings transfer_;  ///< FLIP (with its PIC shares) or APIC (stage keys)
  Real gravity_ = 0;
  std::string stage_name_;
  bool stage_started_ = false;

  Real time_ = 0;
  StepDiagnostics diagnostics_;
  PointTotals totals_;     ///< point sums of the last step's state update
  KineticTotals kinetic_;  ///< kinetic sums of the last step's velocity update
  // The energy scale of the instability bound (stageEnergyScale):
  PointEnergies stage_energies_;  ///< the points' energies at the stage start
  Real load_bound_ = 0;           ///< largest sum of load magnitudes of the stage so far (N/m)
  Real inflow_energy_ = 0;        ///< energy of the liquid that entered in the stage (J/m)
  Real mesh_size_ = 0;            ///< diagonal of the mesh's bounding box (m)
  Real mesh_bottom_ = 0;          ///< lowest y of the mesh (m): the datum of the potential energy
  Real mesh_top_ = 0;             ///< highest y of the mesh (m)
  Real energy_growth_limit_ = 1;
  int sort_interval_ = 0;
  StepProfile profile_;
  std::vector<Kokkos::View<Real*, MemSpace>> output_;  ///< scalar copies for nodalFields()

  // ---- several MPI ranks (distribute())
  Kokkos::View<const int*, MemSpace> alwaysActiveNodes() const;  ///< shared nodes, or none
  const RankDecomposition* ranks_ = nullptr;
  std::unique_ptr<NodalExchange> exchange_;
  ActiveNodes nodes_owned_;          ///< active nodes this rank owns (sums over nodes)
  TimeStepChoice global_choice_;     ///< the last step chosen over all ranks
  RelocationCounts relocation_;      ///< of the last relocation (summed over the ranks)
  TimeStepCandidate candidate_;      ///< this rank's next step, then the ranks' minimum
  bool prepared_time_step_ = false;  ///< candidate_ is the next step (not yet taken)
  TimeStepControl::State state_before_candidate_;  ///< time_step_ before candidate_
  std::vector<Real> reduction_scratch_;            ///< the end-of-step Allreduce buffer
  long long migrated_points_ = 0;
};

}  // namespace argine
