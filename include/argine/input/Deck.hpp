#pragma once
/// @file Deck.hpp
/// The validated input deck as plain structs, in SI units. The deck reader
/// (input/DeckReader) fills these from YAML after checking every key against the schema
/// (input/DeckSchema); the rest of argine reads only these structs, never strings or
/// parameter lists, so nothing is looked up by name inside the time-step loop.

#include <array>
#include <string>
#include <vector>

#include "argine/core/Types.hpp"
#include "argine/materials/MaterialParameters.hpp"
#include "argine/mesh/Mesh.hpp"
#include "argine/timestep/CriterionKind.hpp"

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
  // Rectangle: [x_min, x_max] x [y_min, y_max], one block named `block`; sets
  // "left", "right", "bottom", "top" (node sets and side sets of the same names).
  std::array<Real, 2> lower_left{0.0, 0.0};
  std::array<Real, 2> upper_right{1.0, 1.0};
  std::string block = "soil";
  // Polygon cross-section: soil regions (layers) inside a background box; the rest of the
  // box becomes block "empty" (no material points, room for run-out).
  std::vector<PolygonRegion> regions;
};

struct MeshSpec {
  std::string exodus_file;  ///< absolute path of an Exodus II mesh, or empty
  bool generate = false;    ///< true when `Mesh/Generate` is used instead of a file
  GeneratorSpec generator;
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
  int points_per_element = 3;  ///< 1, 3, 4, 6 or 12
  PhaseModel phase = PhaseModel::Saturated;
  Real porosity = 0.4;        ///< n0 (-)
  Real solid_density = 2650;  ///< rho_S (kg/m^3)
  MassBalanceForm mass_balance = MassBalanceForm::Complete;
  SolidSpec solid;
  LiquidSpec liquid;
  RetentionSpec retention;
  ConductivitySpec conductivity;
  InitialStateSpec initial;
};

// ---------------------------------------------------------------- implicit seepage (P5)
// Settings of an `implicit seepage` stage (seepage room, ImplicitSeepageSolver).

/// The Belos solver and Ifpack2 preconditioner of the implicit seepage path's linear systems.
struct LinearSolverSpec {
  std::string solver = "GMRES";          ///< Belos name: "GMRES" or "CG" (CG: symmetric)
  Real tolerance = 1e-12;                ///< relative residual of each linear solve
  int max_iterations = 1000;             ///< Krylov iterations per solve
  std::string preconditioner = "RILUK";  ///< Ifpack2: RILUK, ILUT, RELAXATION, CHEBYSHEV, NONE
  int fill_level = 1;                    ///< RILUK level of fill / ILUT level-of-fill
  std::string relaxation = "Symmetric Gauss-Seidel";  ///< RELAXATION type
  int sweeps = 2;                                     ///< RELAXATION sweeps / CHEBYSHEV degree
};

struct ImplicitSeepageSpec {
  Real theta = 1;                      ///< 1: backward Euler, 1/2: Crank-Nicolson
  Real initial_step = 1;               ///< first time step (s)
  Real min_step = 1e-6;                ///< below this a failed step stops the run (s)
  Real max_step = 1e30;                ///< (s)
  bool adaptive = true;                ///< false: every step is initial_step
  Real max_saturation_change = 0.05;   ///< target max |dS_L| per step at any point
  int max_picard_iterations = 30;      ///< per step (and per active-set pass)
  int max_active_set_iterations = 30;  ///< seepage face / ponding switches per step
  Real pressure_tolerance = 1e-6;      ///< max |dp_L| of the last Picard update (Pa)
  Real mass_tolerance = 1e-12;         ///< |free-node residual| / (storage + flux scale)
  Real min_suction_fraction = 1e-2;    ///< van Genuchten lambda < 0.5: s_reg = this x p_ref
  LinearSolverSpec linear;
};

// ---------------------------------------------------------------- stages

enum class SolverKind { Explicit, FixedSkeleton, QuasiStatic, ImplicitSeepage };

struct TimeStepSpec {
  bool automatic = true;     ///< false: use fixed_step
  Real fixed_step = 0;       ///< (s)
  Real safety_factor = 0.5;  ///< multiplies the minimum critical step
  /// The thesis (Sec. 3.2) uses the minimum of Mieremet (4.67), which covers the Darcy drag,
  /// and the consolidation criterion (4.61).
  std::vector<CriterionKind> criteria{CriterionKind::Mieremet, CriterionKind::Consolidation};
  int update_interval = 1;  ///< recompute the step every N steps
};

enum class BoundaryKind {
  SolidFixity,     ///< zero solid velocity in x and/or y on a node set
  LiquidFixity,    ///< zero relative liquid velocity (impermeable) on a side or node set
  Traction,        ///< total traction vector on a side set (Pa)
  LiquidPressure,  ///< prescribed liquid pressure on a side set (Pa)
  Infiltration,    ///< implicit seepage: prescribed inflow (m/s) on a side set, ponding switch
  SeepageFace,     ///< implicit seepage: potential seepage face on a side set
};

struct BoundarySpec {
  std::string name;
  BoundaryKind kind = BoundaryKind::SolidFixity;
  std::string node_set;  ///< for fixities (either this or side_set)
  std::string side_set;  ///< for tractions, pressures, impermeable sides
  bool fix_x = false;    ///< direction of a fixity
  bool fix_y = false;
  std::array<Real, 2> traction{0.0, 0.0};  ///< (Pa), tension positive along the outward normal
  Real pressure = 0;                       ///< prescribed p_L (Pa, compression positive)
  // implicit seepage (P5) kinds: Infiltration (flux on a side set, ponding switch) and
  // SeepageFace (potential seepage face on a side set)
  Real flux = 0;        ///< Infiltration: inflow normal to the surface (m/s), >= 0
  bool ponding = true;  ///< Infiltration: switch to p_L = 0 when the surface saturates
};

struct StageSpec {
  std::string name;
  SolverKind solver = SolverKind::Explicit;
  Real duration = 0;                 ///< (s)
  Real gravity = 9.81;               ///< magnitude (m/s^2), acting in -y; 0 switches it off
  Real local_damping = 0;            ///< alpha in [0, 1): damping force = -alpha |f| sign(v)
  Real mass_scaling = 1;             ///< factor >= 1 on the nodal masses
  Real output_interval = 0;          ///< (s); 0: only at the end of the stage
  bool reset_displacements = false;  ///< zero the displacements at the start of the stage
  TimeStepSpec time_step;
  std::vector<BoundarySpec> boundaries;
  ImplicitSeepageSpec seepage;  ///< used by `implicit seepage` stages only
};

// ---------------------------------------------------------------- whole deck

struct OutputSpec {
  std::string directory = "results";  ///< relative to the working directory
  std::string name = "argine";        ///< file stem: <name>_grid.e, <name>_points.e
};

struct Deck {
  std::string path;  ///< the deck file (absolute)
  std::string title;
  MeshSpec mesh;
  std::vector<MaterialSpec> materials;
  std::vector<StageSpec> stages;  ///< in the order written in the deck
  OutputSpec output;
};

}  // namespace argine
