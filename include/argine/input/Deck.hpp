#pragma once
/// @file Deck.hpp
/// The validated input deck as plain structs, in SI units. The deck reader
/// (input/DeckReader) fills these from YAML after checking every key against the schema
/// (input/DeckSchema); the rest of argine reads only these structs, never strings or
/// parameter lists, so nothing is looked up by name inside the time-step loop.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include "argine/core/Types.hpp"
#include "argine/materials/MaterialParameters.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/physics/LocalDamping.hpp"
#include "argine/timestep/CriterionKind.hpp"
#include "argine/transfer/TransferScheme.hpp"

namespace argine {

// ---------------------------------------------------------------- mesh

/// A polygonal soil region of a generated cross-section (vertices counter-clockwise, m).
struct PolygonRegion {
  std::string block;                          ///< element block name given to it
  std::vector<std::array<Real, 2>> vertices;  ///< polygon vertices (m)
};

/// A built-in mesh generator request (`Mesh/Generate`).
struct GeneratorSpec {
  enum class Kind { Rectangle, Polygon } kind = Kind::Rectangle;
  ElementType element = ElementType::Quad4;
  Real element_size = 0.1;  ///< target element edge length (m)
  // Rectangle: [x_min, x_max] x [y_min, y_max], one block named `block` (without regions);
  // sets "left", "right", "bottom", "top" (node sets and side sets of the same names).
  std::array<Real, 2> lower_left{0.0, 0.0};
  std::array<Real, 2> upper_right{1.0, 1.0};
  std::string block = "soil";
  // Soil regions (layers) inside the box; the rest of the box becomes block "empty" (no
  // material points, room for run-out). Polygon: the elements follow the region edges.
  // Rectangle (optional): the grid stays structured and each region's material is seeded
  // at the pattern positions inside its polygon (meshio/RectangleRegions.hpp).
  std::vector<PolygonRegion> regions;
};

struct MeshSpec {
  std::string exodus_file;  ///< absolute path of an Exodus II mesh, or empty
  std::string gmsh_file;    ///< absolute path of a gmsh .msh or .geo file, or empty
  bool generate = false;    ///< true when `Mesh/Generate` is used instead of a file
  GeneratorSpec generator;
  ShapeFamily shape_functions = ShapeFamily::Linear;  ///< `Shape Functions`
};

// ---------------------------------------------------------------- materials

/// Initial state of a material's points (before any initialisation stage).
struct InitialStateSpec {
  Real liquid_pressure = 0;             ///< uniform p_L (Pa, compression positive)
  Real vertical_effective_stress = 0;   ///< sigma'_yy (Pa, tension positive)
  Real earth_pressure_coefficient = 1;  ///< K0: sigma'_xx = sigma'_zz = K0 sigma'_yy
};

struct MaterialSpec {
  std::string name;
  std::string block;           ///< mesh element block holding this material
  int points_per_element = 3;  ///< Tri3: 1, 3, 4, 6 or 12; Quad4: 1, 4, 9 or 16
  PhaseModel phase = PhaseModel::Saturated;
  Real porosity = 0.4;        ///< n0 (-)
  Real solid_density = 2650;  ///< rho_S (kg/m^3)
  MassBalanceForm mass_balance = MassBalanceForm::Complete;
  TensionCracks tension_cracks = TensionCracks::PoreSpace;  ///< unsaturated only
  SolidSpec solid;
  LiquidSpec liquid;
  RetentionSpec retention;
  ConductivitySpec conductivity;
  InitialStateSpec initial;
  LockingMitigationSpec locking;  ///< anti-locking averaging (`Locking Mitigation`)
};

// ---------------------------------------------------------------- implicit seepage (P5)
// Settings of an `implicit seepage` stage (seepage room, ImplicitSeepageSolver).

/// The Belos solver and Ifpack2 preconditioner of the implicit seepage path's linear systems.
struct LinearSolverSpec {
  std::string solver = "GMRES";  ///< Belos name: "GMRES" or "CG" (CG: symmetric); "DIRECT": KLU2
  Real tolerance = 1e-12;        ///< relative residual of each linear solve
  int max_iterations = 1000;     ///< Krylov iterations per solve
  std::string preconditioner = "RILUK";  ///< Ifpack2: RILUK, ILUT, RELAXATION, CHEBYSHEV, NONE
  int fill_level = 1;                    ///< RILUK level of fill / ILUT level-of-fill
  std::string relaxation = "Symmetric Gauss-Seidel";  ///< RELAXATION type
  int sweeps = 2;                                     ///< RELAXATION sweeps / CHEBYSHEV degree
};

/// The iteration of the implicit seepage path's non-linear step (ImplicitSeepageSolver.hpp).
enum class SeepageIteration {
  Picard,  ///< modified Picard (Celia et al. 1990): C/dt + theta K(p)
  Newton,  ///< Newton: C/dt + theta (K(p) + dK/dp . (grad p + rho_L g e_y)), non-symmetric
};

struct ImplicitSeepageSpec {
  SeepageIteration iteration = SeepageIteration::Picard;  ///< Nonlinear Solver
  Real theta = 1;                      ///< 1: backward Euler, 1/2: Crank-Nicolson
  Real initial_step = 1;               ///< first time step (s)
  Real min_step = 1e-6;                ///< below this a failed step stops the run (s)
  Real max_step = 1e30;                ///< (s)
  bool adaptive = true;                ///< false: every step is initial_step
  Real max_saturation_change = 0.05;   ///< target max |dS_L| per step at any point
  Real step_error = 100;               ///< target local time error of p_L per step (Pa)
  int max_picard_iterations = 30;      ///< per step (and per active-set pass)
  int max_active_set_iterations = 30;  ///< seepage face / ponding switches per step
  Real pressure_tolerance = 1e-6;      ///< max |dp_L| of the last Picard update (Pa)
  Real mass_tolerance = 1e-12;         ///< |free-node residual| / (storage + flux scale)
  Real min_suction_fraction = 1e-2;    ///< van Genuchten lambda < 0.5: s_reg = this x p_ref
  bool reuse_matrix = false;           ///< Picard matrix of the step's first iteration only (chord)
  LinearSolverSpec linear;
};

// ---------------------------------------------------------------- stages

enum class SolverKind { Explicit, FixedSkeleton, QuasiStatic, ImplicitSeepage };

struct TimeStepSpec {
  bool automatic = true;     ///< false: use fixed_step
  Real fixed_step = 0;       ///< (s)
  Real safety_factor = 0.5;  ///< multiplies the minimum critical step
  /// The thesis (Sec. 3.2) uses the minimum of Mieremet (4.67), which covers the Darcy drag,
  /// and the consolidation criterion (4.61). argine uses Mieremet with the unsaturated liquid
  /// drag (never above the adapted form; the only criterion never above the empirical
  /// critical step in the 139 regular cases of the V5 study, doc/stability.md).
  /// Keep in step with the "Criteria" default of input/DeckKeys.cpp.
  std::vector<CriterionKind> criteria{CriterionKind::MieremetLiquidDrag,
                                      CriterionKind::Consolidation};
  int update_interval = 1;  ///< recompute the step every N steps
};

enum class BoundaryKind {
  SolidFixity,     ///< zero solid velocity in x and/or y on a node set
  LiquidFixity,    ///< zero relative liquid velocity (impermeable) on a side or node set
  Traction,        ///< total traction vector on a side set (Pa)
  LiquidPressure,  ///< prescribed liquid pressure on a side set (Pa)
  FrictionalWall,  ///< rigid wall with Coulomb friction on a side or node set (solid contact)
  SideWalls,       ///< the two walls of a quasi-2D channel, out of the plane (Coulomb friction)
  // Hydraulic conditions on the moving free boundary (thesis Sec. 4.1-4.3), see below.
  TotalHead,       ///< total head H(t) (4.50) on a zone of the free boundary or a side set
  PressureSeries,  ///< prescribed liquid pressure p(t) on a zone or a side set
  Infiltration,    ///< prescribed infiltration flux q(t) (Sec. 4.2); negative: evaporation
  SeepageFace,     ///< potential seepage face (Sec. 4.3)
};

// ---------------------------------------------------------------- hydraulic conditions (P3)
// Plain deck data of the conditions on the moving free boundary; resolved by the boundary
// room (boundary/TimeSeries.hpp, boundary/Zone.hpp, boundary/HydraulicConditions.hpp).

/// A region of the plane where a condition applies on the current free boundary.
struct ZoneSpec {
  enum class Kind { Everywhere, HalfPlane, Box, PolylineBand } kind = Kind::Everywhere;
  std::array<Real, 2> point{0.0, 0.0};        ///< half-plane: a point on its edge (m)
  std::array<Real, 2> direction{0.0, 1.0};    ///< half-plane: pointing into the zone
  std::array<Real, 2> lower_left{0.0, 0.0};   ///< box (m)
  std::array<Real, 2> upper_right{0.0, 0.0};  ///< box (m)
  std::vector<std::array<Real, 2>> vertices;  ///< polyline band (m)
  Real width = 0;                             ///< polyline band half-width (m)
};

/// What the times of a table or file count from: the start of the stage that holds the
/// condition (default), or the start of the simulation (the first stage).
enum class TimeOrigin { StageStart, SimulationStart };

/// A time-dependent value as written in the deck: a constant, an inline table of pairs
/// (t, v), or a CSV file; `where` is the key path for error messages.
struct TimeSeriesSpec {
  enum class Source { Constant, Table, File } source = Source::Constant;
  Real value = 0;                              ///< Constant (SI)
  std::vector<Real> pairs;                     ///< Table: t0, v0, t1, v1, ... (s, SI)
  std::string file;                            ///< File: absolute path of the two-column CSV
  std::string where;                           ///< deck key path of the value
  TimeOrigin origin = TimeOrigin::StageStart;  ///< what the table's or file's times count from
};

/// What a total-head condition does on the free boundary above the current level (Sec. 4.1).
enum class AboveLevel {
  ConstantPressure,  ///< p_L = Pressure Above Level (Pa), default 0
  LinearSuction,     ///< p_L = rho_L g (H - y) < 0: hydrostatic suction
  SeepageFace,       ///< potential seepage face (Sec. 4.3)
};

/// Parameters of the hydraulic kinds (TotalHead, PressureSeries, Infiltration, SeepageFace).
struct HydraulicSpec {
  bool on_zone = false;  ///< true: the zone on the free boundary; false: BoundarySpec::side_set
  ZoneSpec zone;
  TimeSeriesSpec series;  ///< head (m), pressure (Pa) or flux (m/s, infiltration positive)
  /// Pressure series only: p_L linear in x from `series` at x_range[0] to `end_series` at
  /// x_range[1], constant beyond (boundary/LinearInX.hpp); false: uniform along the boundary.
  bool linear_in_x = false;
  std::array<Real, 2> x_range{0.0, 0.0};  ///< x0 < x1 (m)
  TimeSeriesSpec end_series;              ///< p_L at x1 (Pa)
  AboveLevel above = AboveLevel::ConstantPressure;
  Real pressure_above = 0;  ///< (Pa) for AboveLevel::ConstantPressure
  bool ponding = false;     ///< infiltration: rain that cannot infiltrate ponds (true) or runs off
  Real liquid_density = 1000;  ///< rho_L of the head-pressure conversion (kg/m^3)
};
// ---------------------------------------------------------------- end hydraulic conditions

struct BoundarySpec {
  std::string name;
  BoundaryKind kind = BoundaryKind::SolidFixity;
  std::string node_set;  ///< for fixities (either this or side_set)
  std::string side_set;  ///< for tractions, pressures, impermeable sides
  bool fix_x = false;    ///< direction of a fixity
  bool fix_y = false;
  std::array<Real, 2> traction{0.0, 0.0};  ///< (Pa), tension positive along the outward normal
  Real pressure = 0;                       ///< prescribed p_L (Pa, compression positive)
  HydraulicSpec hydraulic;                 ///< TotalHead, PressureSeries, Infiltration, ...
  // FrictionalWall (boundary/FrictionalContact.hpp):
  Real friction_coefficient = 0;         ///< Coulomb mu >= 0 (0: smooth wall)
  bool has_normal = false;               ///< node set: `normal` given instead of the mesh geometry
  std::array<Real, 2> normal{0.0, 0.0};  ///< unit outward normal of the soil (into the wall)
  bool wall_impermeable = true;          ///< zero relative liquid velocity normal to the wall
  // SideWalls (boundary/SideWalls.hpp; friction_coefficient above is their mu):
  Real channel_width = 0;  ///< distance W between the walls (m)
};

// ---- stages: relaxation and material changes (issue P4) ----

/// Ends a stage early once it is quasi-static: the largest kinetic energy over the last
/// `window` seconds, divided by the stored elastic energy, is below
/// `kinetic_energy_ratio` (simulation/RelaxationMonitor.hpp). The window keeps an
/// oscillation's turning point (kinetic energy momentarily ~0) from passing for rest.
/// Duration stays the maximum.
struct RelaxationSpec {
  bool enabled = false;
  Real kinetic_energy_ratio = 1e-4;  ///< tolerance (-)
  Real window = 0.1;                 ///< (s) time the ratio must stay low
};

/// `Hand Back At Rest` of an explicit stage (P12): once no point has moved more than
/// `largest_speed` times the window's length over a window of at least `window`, the rest of
/// the stage runs on the implicit seepage path (fixed skeleton, the stage's conditions and
/// `Implicit Seepage` settings; simulation/RestMonitor.hpp).
struct HandBackSpec {
  bool enabled = false;
  Real largest_speed = 0;  ///< (m/s)
  Real window = 0;         ///< (s)
};

/// New values of some parameters of one material, applied when the stage starts (e.g. the
/// cohesion falling from 20 to 2 kPa). Unset values keep the material's current ones.
struct MaterialChangeSpec {
  std::string material;                        ///< material name (Materials/<name>)
  std::optional<Real> youngs_modulus;          ///< (Pa)
  std::optional<Real> poisson_ratio;           ///< (-)
  std::optional<Real> cohesion;                ///< (Pa)
  std::optional<Real> friction_angle;          ///< (rad)
  std::optional<Real> dilatancy_angle;         ///< (rad)
  std::optional<Real> tensile_strength;        ///< (Pa)
  std::optional<Real> intrinsic_permeability;  ///< kappa (m2)
  std::optional<Real> saturated_conductivity;  ///< k_sat (m/s)
};

// ---- end of issue P4 stage additions ----

/// What makes a strength-reduction trial fail (P13 item 3; simulation/StrengthReductionTrial).
enum class StrengthReductionCriterion {
  NonConvergence,            ///< the quasi-static solution does not relax within the trial
  AcceleratingDisplacement,  ///< the mobilised mass moves faster in the trial's second half
  Either,                    ///< either of the two
  /// the mobilised mass still moves Minimum Displacement (m) in the trial's last quarter
  ContinuingDisplacement,
};

/// A stage's `Strength Reduction` (P13 item 3): the stage becomes a strength-reduction
/// analysis. Each trial starts from the state the stage found, divides c, tan phi (with the
/// suction terms) and the cut-off of every Mohr-Coulomb material by a factor F and runs the
/// stage's quasi-static steps for its Duration (s), judged at the end; the factors bracket, then
/// bisect, the smallest failing F (simulation/StrengthReductionSearch.hpp). The stage leaves the
/// state and the materials as it found them.
struct StrengthReductionSpec {
  bool enabled = false;
  Real initial_factor = 1;    ///< the first trial's F (-)
  Real factor_step = 0.2;     ///< first step of F while bracketing, doubled each time (-)
  Real tolerance = 0.01;      ///< bisection until (F_fail - F_stable)/2 <= this (-)
  Real minimum_factor = 0.1;  ///< below this the search stops: fails at the minimum (-)
  Real maximum_factor = 5;    ///< above this the search stops: stable at the maximum (-)
  StrengthReductionCriterion criterion = StrengthReductionCriterion::NonConvergence;
  Real minimum_displacement = 1e-3;  ///< (m) the mobilised mass must move this much to fail
};

struct StageSpec {
  std::string name;
  SolverKind solver = SolverKind::Explicit;
  Real duration = 0;       ///< (s)
  Real gravity = 9.81;     ///< magnitude (m/s^2), acting in -y; 0 switches it off
  Real local_damping = 0;  ///< alpha in [0, 1): damping force = -alpha |f| sign(v)
  Real mass_scaling = 1;   ///< factor >= 1 on the nodal masses
  TransferScheme transfer = TransferScheme::Flip;  ///< `Velocity Transfer`
  Real solid_pic_fraction = 0;   ///< FLIP: PIC share of the solid velocity update (VelocityBlend)
  Real liquid_pic_fraction = 0;  ///< FLIP: PIC share of the liquid velocity update
  Real solid_pic_rate = 0;       ///< FLIP, APIC: (1/s) the solid's grid share per second; 0: none
  Real liquid_pic_rate = 0;      ///< FLIP, APIC: (1/s) the liquid's grid share per second; 0: none
  /// XPIC: `XPIC Order` m and, with `XPIC Polynomial: Chebyshev`, `XPIC Lower Eigenvalue`
  XpicPolynomial xpic{};
  /// `Liquid Pressure: held` (quasi-static stages): p_L and S_L stay as the stage found them
  /// while the skeleton settles into equilibrium with them; the liquid moves with the solid.
  bool hold_liquid_pressure = false;
  /// `Liquid Drag: implicit`: the Darcy drag at the new velocities, solved node by node with
  /// the mixture equation (MomentumBalance.hpp); false: at t^k, the thesis' explicit scheme.
  bool implicit_drag = false;
  /// `Local Damping Form`: start-of-step (-alpha |f| sign(v^k), the default) or dissipative
  /// (physics/LocalDamping.hpp).
  LocalDampingForm local_damping_form = LocalDampingForm::StartOfStep;
  /// `Liquid At Solid Fixities`: `velocity` (false, the thesis) keeps the liquid's mapped
  /// velocity at a solid-fixed, permeable node direction; `relative velocity` (true) keeps
  /// its mapped velocity relative to the solid (NodalConstraints::constrainVelocities).
  bool fixity_keeps_relative_velocity = false;
  /// `Hydraulic Loads`: `on free sides` (false, the thesis) gives each free side's pressure
  /// load to its end nodes; `at boundary points` (true) passes it through the points that
  /// carry those nodes (physics/PointBorneLoads.hpp); `by mesh` (the default): true on a
  /// rectangle with Regions, false on meshes that follow the soil's outline.
  bool hydraulic_loads_at_points = false;
  /// `Hydraulic Loads: through the soil`: the total-head condition's hydrostatic pressure
  /// field loads the soil through its points' volume (physics/HeadLoadsThroughSoil.hpp); its
  /// other loads (pressure series) go at boundary points (hydraulic_loads_at_points is true).
  bool hydraulic_heads_through_soil = false;
  /// `Surfaces Without Condition`: `atmosphere` (true, the default) gives every free side
  /// under no hydraulic condition the rule of a seepage face (it drains at p_L >= 0 and lets
  /// no liquid in at suction: the air has no water to give); `open` (false, the thesis)
  /// leaves the natural condition of 4.36, p_L = 0, which draws water in at suction.
  bool atmosphere_on_free_surfaces = true;
  /// `Interior Liquid Balance`: `point` (false, the thesis) or `conservative` (true): the
  /// liquid the point mass balance makes at nodes inside the body is given back by the
  /// points around them (physics/InteriorLiquidBalance.hpp).
  bool interior_liquid_conservative = false;
  /// `Free Surface Liquid Pressure`: `zero` (false, the thesis) or `suction held` (true):
  /// where the soil's liquid is at suction its free surfaces carry that suction, so the air
  /// pulls on no water (physics/FreeSurfaceSuction.hpp).
  bool free_surface_suction_held = false;
  Real output_interval = 0;          ///< (s); 0: only at the end of the stage
  bool reset_displacements = false;  ///< zero the displacements at the start of the stage
  TimeStepSpec time_step;
  std::vector<BoundarySpec> boundaries;
  /// used by `implicit seepage` stages, and by explicit ones after a hand-back (P12)
  ImplicitSeepageSpec seepage;
  RelaxationSpec relaxation;  ///< optional early end (issue P4)
  HandBackSpec hand_back;     ///< (P12) explicit stages: the rest implicit once at rest
  std::vector<MaterialChangeSpec> material_changes;  ///< applied at the stage start (P4)
  /// (P13) end the stage at the first output whose factor of safety is below this; 0: never
  Real hand_over_below_factor_of_safety = 0;
  StrengthReductionSpec strength_reduction;  ///< (P13) enabled: a strength-reduction analysis
};

/// `Hydraulic Loads: through the soil` (StageSpec::hydraulic_heads_through_soil): the index in
/// `stage.boundaries` of its one total head; InputError unless the stage has exactly one and
/// its pressure is continuous at its level (a jump would load the soil inside). -1 when the
/// stage does not load through the soil.
int headThroughSoil(const StageSpec& stage);

// ---------------------------------------------------------------- initialisation (P4)

/// How the points' initial stress and liquid pressure are set before the first stage.
///   Uniform: each material's Initial State (uniform p_L and sigma'_yy); gravity loading is
///            this followed by a (quasi-static) stage with gravity.
///   K0Procedure: thesis Ch. 4 Sec. 5.1 (Figs. 4.6-4.7): hydrostatic p_L under a phreatic
///            surface (capped suction above it), sigma_yy from the unit weight of the layers
///            between the ground surface and the point, Bishop sigma'_yy, sigma'_xx = K0
///            sigma'_yy with each material's Initial State K0 (init/K0Procedure.hpp).
struct InitialisationSpec {
  /// PorePressure (P10): p_L from a phreatic surface or a table, the stress as each
  /// material's Initial State (no K0 stress).
  enum class Method { Uniform, K0Procedure, PorePressure } method = Method::Uniform;
  std::vector<std::array<Real, 2>> ground_surface;    ///< (x, y) vertices, x increasing (m)
  std::vector<std::array<Real, 2>> phreatic_surface;  ///< (m); empty: each material's uniform p_L
  Real max_suction = -1;                              ///< (Pa); < 0: no cap (Fig. 4.7 b)
  /// PorePressure: (y (m), p_L (Pa)) pairs, y increasing; empty: from the phreatic surface.
  std::vector<std::array<Real, 2>> pore_pressure_table;
};

// ---------------------------------------------------------------- probes (P4)

/// A material point followed through the run: the point nearest to `position` at the start.
struct PointProbeSpec {
  std::string name;
  std::array<Real, 2> position{0.0, 0.0};  ///< initial position sought (m)
  Real tolerance = 0;                      ///< the nearest point must lie this close (m)
};

/// A line segment through the soil: either every point within `band_width`/2 of it (Band),
/// or p_L and S_L interpolated at `samples` equidistant positions on it (Profile).
struct SectionProbeSpec {
  enum class Kind { Band, Profile } kind = Kind::Profile;
  std::string name;
  std::array<Real, 2> from{0.0, 0.0};  ///< (m)
  std::array<Real, 2> to{0.0, 0.0};    ///< (m)
  Real band_width = 0;                 ///< (m) band width; for a profile the averaging radius
  int samples = 10;                    ///< Profile: number of sample positions
};

struct ProbesSpec {
  Real interval = 0;  ///< (s) between probe rows; 0: at every output
  std::vector<PointProbeSpec> points;
  std::vector<SectionProbeSpec> sections;
  bool empty() const { return points.empty() && sections.empty(); }
};

// ---------------------------------------------------------------- whole deck

/// Output/Checkpoint (P8): when to write `<directory>/<name>.checkpoint`.
struct CheckpointSpec {
  long long every_steps = 0;  ///< after every this many steps over all stages; 0: never
  Real wall_interval = 0;     ///< (s) of wall time since the last one; 0: never
  bool enabled() const { return every_steps > 0 || wall_interval > 0; }
};

struct OutputSpec {
  std::string directory = "results";  ///< relative to the working directory
  std::string name = "argine";        ///< file stem: <name>_grid.e, <name>_points.e
  CheckpointSpec checkpoint;          ///< (P8)
};

// ---- physical guards of a run (issue P8) ----

/// What happens when material points leave the background mesh.
enum class LeavingPoints {
  Stop,    ///< RunError naming time, step, point id and position; the last output is kept
  Remove,  ///< taken out of the computation (velocities and masses zeroed), counted in the log
};

/// Bounds checked after every explicit step; each warns once per run, with the numbers.
struct GuardsSpec {
  LeavingPoints leaving_points = LeavingPoints::Stop;
  /// |liquid storage change - net inflow| / initial liquid volume (runs with hydraulic
  /// conditions, where the net inflow is known).
  Real mass_balance_bound = 1e-3;
  /// kinetic energy / the stage's energy scale (the run stops at 10 x the scale).
  Real kinetic_energy_bound = 0.1;
};

/// How a run over MPI ranks adds up (P7; doc/parallel.md).
struct ParallelSpec {
  /// Compensated node sums (transfer/CompensatedSum.hpp): results independent of the number
  /// of ranks and of the points' order, also through local damping; ~2x in the P2G kernels.
  bool reproducible_sums = false;
};

// ---------------------------------------------------------------- factor of safety (P13)

/// How matric suction s = -p_L adds shear strength on a slip surface
/// (simulation/SlipSurfaceStrength.hpp).
enum class SuctionStrength { SolidModel, Vanapalli, Fredlund, None };

/// `Factor Of Safety`: Bishop's critical circle on the points' state at every output
/// (simulation/FactorOfSafetyMonitor.hpp). Unset ranges follow from the ground.
struct FactorOfSafetySpec {
  bool enabled = false;
  bool spencer = false;  ///< `Method: spencer` (else Bishop's simplified method)
  std::optional<std::array<Real, 2>> centre_x, centre_y, tangent_y;  ///< search ranges (m)
  int grid_count = 11;
  int refinements = 3;
  int search_starts = 8;
  int slices = 50;
  Real min_depth = 0;                               ///< (m)
  std::optional<std::array<Real, 2>> mass_x_range;  ///< (m)
  SuctionStrength suction = SuctionStrength::SolidModel;
  Real suction_friction_angle = 0;                  ///< phi_b (rad), fredlund
  std::vector<std::array<Real, 2>> ground_surface;  ///< (m); empty: envelope of the points
  Real cell_size = 0;                               ///< (m); 0: automatic
  bool slice_table = true;
};

struct Deck {
  std::string path;  ///< the deck file (absolute)
  std::string title;
  MeshSpec mesh;
  std::vector<MaterialSpec> materials;
  std::vector<StageSpec> stages;  ///< in the order written in the deck
  OutputSpec output;
  InitialisationSpec initialisation;    ///< (P4)
  ProbesSpec probes;                    ///< (P4)
  GuardsSpec guards;                    ///< (P8)
  ParallelSpec parallel;                ///< (P7)
  FactorOfSafetySpec factor_of_safety;  ///< (P13)
};

}  // namespace argine
