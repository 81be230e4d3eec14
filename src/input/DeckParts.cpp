#include "DeckParts.hpp"

#include <algorithm>
#include <cmath>

#include "argine/core/Error.hpp"
#include "argine/input/DeckWords.hpp"

namespace argine::input_detail {

namespace {

constexpr Real kPi = 3.14159265358979323846;
Real radians(Real degrees) {
  return degrees * kPi / 180.0;
}

std::array<Real, 2> pair(const std::vector<double>& values) {
  return {values[0], values[1]};
}

/// Twice the signed area of a polygon (> 0 when counter-clockwise).
Real twiceSignedArea(const std::vector<std::array<Real, 2>>& vertices) {
  Real sum = 0;
  for (std::size_t i = 0; i < vertices.size(); ++i) {
    const auto& a = vertices[i];
    const auto& b = vertices[(i + 1) % vertices.size()];
    sum += a[0] * b[1] - b[0] * a[1];
  }
  return sum;
}

PolygonRegion parseRegion(const DeckSection& region) {
  const std::vector<double> values = region.reals("Vertices (m)");
  const std::string where = region.pathOf("Vertices (m)");
  if (values.size() % 2 != 0)
    throw InputError(where, "expected x, y pairs (an even count of numbers), got " +
                                std::to_string(values.size()) + " numbers");
  if (values.size() < 6)
    throw InputError(
        where, "a polygon needs at least 3 vertices, got " + std::to_string(values.size() / 2));
  PolygonRegion polygon;
  polygon.block = region.name();
  for (std::size_t i = 0; i < values.size(); i += 2)
    polygon.vertices.push_back({values[i], values[i + 1]});
  // Either orientation is accepted; the generator wants counter-clockwise.
  if (twiceSignedArea(polygon.vertices) < 0)
    std::reverse(polygon.vertices.begin(), polygon.vertices.end());
  return polygon;
}

SolidSpec parseSolid(const DeckSection& solid) {
  SolidSpec spec;
  spec.model = deckValue(kSolidModelWords, solid.word("Model"));
  spec.youngs_modulus = solid.real("Young's Modulus (Pa)");
  spec.poisson_ratio = solid.real("Poisson's Ratio");
  if (spec.model == SolidModel::LinearElastic) return spec;
  spec.cohesion = solid.real("Cohesion (Pa)");
  spec.friction_angle = radians(solid.real("Friction Angle (deg)"));
  spec.dilatancy_angle = radians(solid.real("Dilatancy Angle (deg)"));
  spec.tensile_strength = solid.real("Tensile Strength (Pa)");
  spec.tension_cutoff = solid.boolean("Tension Cut-Off");
  if (spec.model == SolidModel::MohrCoulomb) return spec;
  spec.cohesion_increase_max = solid.real("Cohesion Increase Max (Pa)");
  spec.cohesion_suction_rate = solid.real("Cohesion Suction Rate B");
  spec.friction_suction_rate = radians(solid.real("Friction Suction Rate A (deg)"));
  spec.atmospheric_pressure = solid.real("Atmospheric Pressure (Pa)");
  return spec;
}

LiquidSpec parseLiquid(const DeckSection& liquid) {
  LiquidSpec spec;
  spec.density = liquid.real("Density (kg/m3)");
  spec.bulk_modulus = liquid.real("Bulk Modulus (Pa)");
  spec.viscosity = liquid.real("Viscosity (Pa s)");
  return spec;
}

RetentionSpec parseRetention(const DeckSection& retention) {
  RetentionSpec spec;
  spec.model = deckValue(kRetentionModelWords, retention.word("Model"));
  switch (spec.model) {
    case RetentionModel::Linear:
      spec.linear_slope = retention.real("Slope (1/Pa)");
      break;
    case RetentionModel::VanGenuchten:
      spec.reference_pressure = retention.real("Reference Pressure (Pa)");
      spec.lambda = retention.real("Lambda");
      break;
    case RetentionModel::Gardner:
      spec.gardner_alpha = retention.real("Alpha (1/Pa)");
      break;
  }
  spec.saturation_min = retention.real("Minimum Saturation");
  spec.saturation_max = retention.real("Maximum Saturation");
  spec.occluded_air_pressure = retention.real("Occluded Air Pressure (Pa)");
  return spec;
}

/// Either kappa or k_sat is given; the other follows from k_sat = kappa rho_L g / mu_L.
ConductivitySpec parseConductivity(const DeckSection& conductivity, const LiquidSpec& liquid) {
  ConductivitySpec spec;
  spec.model = deckValue(kConductivityModelWords, conductivity.word("Model"));
  const Real kappa_to_k = liquid.density * kStandardGravity / liquid.viscosity;
  if (conductivity.has("Intrinsic Permeability (m2)")) {
    spec.intrinsic_permeability = conductivity.real("Intrinsic Permeability (m2)");
    spec.saturated_conductivity = spec.intrinsic_permeability * kappa_to_k;
  } else {
    spec.saturated_conductivity = conductivity.real("Saturated Conductivity (m/s)");
    spec.intrinsic_permeability = spec.saturated_conductivity / kappa_to_k;
  }
  switch (spec.model) {
    case ConductivityModel::Constant:
      break;
    case ConductivityModel::Hillel:
      spec.hillel_exponent = conductivity.real("Exponent");
      break;
    case ConductivityModel::Mualem:
      spec.mualem_lambda = conductivity.real("Lambda");
      break;
    case ConductivityModel::Gardner:
      spec.gardner_alpha = conductivity.real("Alpha (1/Pa)");
      break;
  }
  return spec;
}

InitialStateSpec parseInitialState(const DeckSection& initial, bool wet) {
  InitialStateSpec spec;
  if (wet) spec.liquid_pressure = initial.real("Liquid Pressure (Pa)");
  spec.vertical_effective_stress = initial.real("Vertical Effective Stress (Pa)");
  spec.earth_pressure_coefficient = initial.real("K0");
  return spec;
}

TimeStepSpec parseTimeStep(const DeckSection& step) {
  TimeStepSpec spec;
  spec.automatic = deckValue(kTimeStepModeWords, step.word("Mode"));
  if (!spec.automatic) spec.fixed_step = step.real("Fixed Step (s)");
  // With a fixed step these keep their defaults, so the critical step can still be
  // reported next to the fixed one.
  spec.safety_factor = step.real("Safety Factor");
  spec.update_interval = static_cast<int>(step.integer("Update Interval"));
  spec.criteria.clear();
  for (const auto& word : step.words("Criteria"))
    spec.criteria.push_back(deckValue(kCriterionWords, word));
  return spec;
}

// ---------------------------------------------------------------- hydraulic conditions (P3)

ZoneSpec parseZone(const DeckSection& zone) {
  ZoneSpec spec;
  spec.kind = deckValue(kZoneWords, zone.word("Type"));
  switch (spec.kind) {
    case ZoneSpec::Kind::Everywhere:
      break;
    case ZoneSpec::Kind::HalfPlane:
      spec.point = pair(zone.reals("Point (m)"));
      spec.direction = pair(zone.reals("Inside Direction"));
      if (spec.direction[0] == 0 && spec.direction[1] == 0)
        throw InputError(zone.pathOf("Inside Direction"), "a non-zero vector is needed");
      break;
    case ZoneSpec::Kind::Box:
      spec.lower_left = pair(zone.reals("Lower Left (m)"));
      spec.upper_right = pair(zone.reals("Upper Right (m)"));
      if (!(spec.lower_left[0] < spec.upper_right[0] && spec.lower_left[1] < spec.upper_right[1]))
        throw InputError(zone.pathOf("Upper Right (m)"),
                         "the upper right corner must lie above and right of the lower left");
      break;
    case ZoneSpec::Kind::PolylineBand: {
      const std::vector<double> values = zone.reals("Vertices (m)");
      if (values.size() < 4 || values.size() % 2 != 0)
        throw InputError(zone.pathOf("Vertices (m)"),
                         "expected x, y pairs of at least 2 vertices, got " +
                             std::to_string(values.size()) + " numbers");
      for (std::size_t i = 0; i < values.size(); i += 2)
        spec.vertices.push_back({values[i], values[i + 1]});
      spec.width = zone.real("Width (m)");
      break;
    }
  }
  return spec;
}

/// The time series of `value` (see addTimeSeriesKeys in DeckKeys.cpp): constant, table or file.
TimeSeriesSpec parseTimeSeries(const DeckSection& boundary, const std::string& value,
                               const std::string& unit) {
  TimeSeriesSpec spec;
  const std::string constant = value + " (" + unit + ")";
  if (boundary.has(value + " Table")) {
    spec.source = TimeSeriesSpec::Source::Table;
    spec.where = boundary.pathOf(value + " Table");
    const std::vector<double> pairs = boundary.reals(value + " Table");
    spec.pairs.assign(pairs.begin(), pairs.end());
  } else if (boundary.has(value + " File")) {
    spec.source = TimeSeriesSpec::Source::File;
    spec.where = boundary.pathOf(value + " File");
    spec.file = boundary.file(value + " File");
  } else {
    spec.source = TimeSeriesSpec::Source::Constant;
    spec.where = boundary.pathOf(constant);
    spec.value = boundary.real(constant);
  }
  spec.origin = deckValue(kTimeOriginWords, boundary.word("Time Origin"));
  return spec;
}

/// A pressure series' optional x-dependence: `Linear Between x (m)` with exactly one of
/// `End Pressure Table` / `End Pressure File`, or none of the three.
void parseLinearInX(const DeckSection& boundary, HydraulicSpec& spec) {
  const std::string range = "Linear Between x (m)";
  const bool table = boundary.has("End Pressure Table"), file = boundary.has("End Pressure File");
  if (!boundary.has(range)) {
    if (table || file)
      throw InputError(boundary.pathOf(table ? "End Pressure Table" : "End Pressure File"),
                       "an end pressure needs 'Linear Between x (m): [x0, x1]', the two "
                       "abscissas between which p_L varies linearly");
    return;
  }
  const std::array<Real, 2> x = pair(boundary.reals(range));
  if (!(x[1] > x[0]))
    throw InputError(boundary.pathOf(range), "expected x0 < x1, got [" + std::to_string(x[0]) +
                                                 ", " + std::to_string(x[1]) + "]");
  if (table == file)
    throw InputError(boundary.pathOf(range),
                     table ? "give one of 'End Pressure Table' or 'End Pressure File', not both"
                           : "give 'End Pressure Table' or 'End Pressure File': p_L at x1 in "
                             "time");
  spec.linear_in_x = true;
  spec.x_range = x;
  spec.end_series = parseTimeSeries(boundary, "End Pressure", "Pa");
}

HydraulicSpec parseHydraulic(const DeckSection& boundary, BoundaryKind kind) {
  HydraulicSpec spec;
  spec.on_zone = boundary.has("Zone");
  if (spec.on_zone) spec.zone = parseZone(boundary.section("Zone"));
  switch (kind) {
    case BoundaryKind::TotalHead:
      spec.series = parseTimeSeries(boundary, "Total Head", "m");
      spec.above = deckValue(kAboveLevelWords, boundary.word("Above Level"));
      if (spec.above == AboveLevel::ConstantPressure)
        spec.pressure_above = boundary.real("Pressure Above Level (Pa)");
      spec.liquid_density = boundary.real("Liquid Density (kg/m3)");
      break;
    case BoundaryKind::PressureSeries:
      spec.series = parseTimeSeries(boundary, "Pressure", "Pa");
      parseLinearInX(boundary, spec);
      break;
    case BoundaryKind::Infiltration:
      spec.series = parseTimeSeries(boundary, "Flux", "m/s");
      spec.ponding = boundary.boolean("Ponding");
      break;
    default:
      break;
  }
  return spec;
}
// ---------------------------------------------------------------- end hydraulic conditions

/// The keys of a frictional wall; the wall normal of a node set, normalised.
void parseFrictionalWall(const DeckSection& boundary, BoundarySpec& spec) {
  if (boundary.has("Node Set")) spec.node_set = boundary.text("Node Set");
  if (boundary.has("Side Set")) spec.side_set = boundary.text("Side Set");
  spec.friction_coefficient = boundary.real("Friction Coefficient (-)");
  spec.wall_impermeable = boundary.boolean("Impermeable");
  if (!boundary.has("Normal")) return;
  const std::string where = boundary.pathOf("Normal");
  // A side set's normals come from its sides; a second, different source would be ambiguous.
  if (!spec.side_set.empty())
    throw InputError(where,
                     "Normal is for a Node Set; a side set's wall normal comes from "
                     "its sides (outward normal of the mesh)");
  const std::array<Real, 2> normal = pair(boundary.reals("Normal"));
  const Real length = std::hypot(normal[0], normal[1]);
  if (!(length > 0) || !std::isfinite(length))
    throw InputError(where,
                     "expected a non-zero finite vector (the outward normal of the "
                     "soil, pointing into the wall)");
  spec.has_normal = true;
  spec.normal = {normal[0] / length, normal[1] / length};
}

BoundarySpec parseBoundary(const DeckSection& boundary) {
  BoundarySpec spec;
  spec.name = boundary.name();
  spec.kind = deckValue(kBoundaryWords, boundary.word("Type"));
  switch (spec.kind) {
    case BoundaryKind::SolidFixity: {
      spec.node_set = boundary.text("Node Set");
      const FixedDirections fixed = deckValue(kDirectionWords, boundary.word("Direction"));
      spec.fix_x = fixed.x;
      spec.fix_y = fixed.y;
      break;
    }
    case BoundaryKind::LiquidFixity:
      if (boundary.has("Node Set")) spec.node_set = boundary.text("Node Set");
      if (boundary.has("Side Set")) spec.side_set = boundary.text("Side Set");
      break;
    case BoundaryKind::Traction:
      spec.side_set = boundary.text("Side Set");
      spec.traction = pair(boundary.reals("Traction (Pa)"));
      break;
    case BoundaryKind::LiquidPressure:
      spec.side_set = boundary.text("Side Set");
      spec.pressure = boundary.real("Pressure (Pa)");
      break;
    case BoundaryKind::FrictionalWall:
      parseFrictionalWall(boundary, spec);
      break;
    case BoundaryKind::SideWalls:
      spec.friction_coefficient = boundary.real("Friction Coefficient (-)");
      spec.channel_width = boundary.real("Channel Width (m)");
      break;
    case BoundaryKind::TotalHead:
    case BoundaryKind::PressureSeries:
    case BoundaryKind::Infiltration:
    case BoundaryKind::SeepageFace:
      if (boundary.has("Side Set")) spec.side_set = boundary.text("Side Set");
      spec.hydraulic = parseHydraulic(boundary, spec.kind);
      break;
  }
  return spec;
}

// ---------------------------------------------------------------- implicit seepage (P5)

LinearSolverSpec parseLinearSolver(const DeckSection& linear) {
  LinearSolverSpec spec;
  const std::string solver = linear.word("Solver");
  spec.solver = solver == "cg" ? "CG" : solver == "direct" ? "DIRECT" : "GMRES";
  spec.tolerance = linear.real("Tolerance");
  spec.max_iterations = static_cast<int>(linear.integer("Maximum Iterations"));
  const std::string preconditioner = linear.word("Preconditioner");
  spec.preconditioner = preconditioner == "riluk"        ? "RILUK"
                        : preconditioner == "ilut"       ? "ILUT"
                        : preconditioner == "relaxation" ? "RELAXATION"
                        : preconditioner == "chebyshev"  ? "CHEBYSHEV"
                                                         : "NONE";
  spec.fill_level = static_cast<int>(linear.integer("Fill Level"));
  spec.sweeps = static_cast<int>(linear.integer("Sweeps"));
  return spec;
}

ImplicitSeepageSpec parseImplicitSeepage(const DeckSection& seepage) {
  ImplicitSeepageSpec spec;
  spec.theta = seepage.real("Theta");
  spec.initial_step = seepage.real("Initial Step (s)");
  spec.min_step = seepage.real("Minimum Step (s)");
  if (seepage.has("Maximum Step (s)")) spec.max_step = seepage.real("Maximum Step (s)");
  spec.adaptive = seepage.boolean("Adaptive Step");
  spec.reuse_matrix = seepage.boolean("Reuse Matrix");
  spec.max_saturation_change = seepage.real("Maximum Saturation Change");
  spec.step_error = seepage.real("Step Error (Pa)");
  spec.max_picard_iterations = static_cast<int>(seepage.integer("Picard Iterations"));
  spec.pressure_tolerance = seepage.real("Pressure Tolerance (Pa)");
  spec.mass_tolerance = seepage.real("Mass Tolerance");
  spec.min_suction_fraction = seepage.real("Minimum Suction Fraction");
  spec.linear = parseLinearSolver(seepage.section("Linear Solver"));
  spec.iteration = seepage.word("Nonlinear Solver") == "newton" ? SeepageIteration::Newton
                                                                : SeepageIteration::Picard;
  // CG needs a symmetric positive definite matrix; Newton's Jacobian is not symmetric.
  if (spec.iteration == SeepageIteration::Newton && spec.linear.solver == "CG")
    throw InputError(seepage.section("Linear Solver").pathOf("Solver"),
                     "gmres or direct with Nonlinear Solver: newton (its Jacobian is not "
                     "symmetric, cg needs a symmetric matrix)");
  return spec;
}

// ---- Locking mitigation (volumetric averaging)
LockingMitigationSpec parseLockingMitigation(const DeckSection& locking) {
  LockingMitigationSpec spec;
  spec.volumetric_strain =
      deckValue(kIncrementAveragingWords, locking.word("Volumetric Strain Averaging"));
  spec.liquid_pressure =
      deckValue(kIncrementAveragingWords, locking.word("Liquid Pressure Averaging"));
  spec.head_stabilisation = locking.real("Liquid Head Stabilisation");
  spec.intra_element_seepage = locking.boolean("Intra-Element Seepage");
  spec.seepage_patch = deckValue(kSeepagePatchWords, locking.word("Seepage Patch"));
  spec.averaging_length = locking.real("Averaging Length (m)");
  spec.checkerboard_filter = locking.boolean("Checkerboard Filter");
  spec.conjugate_mean_stress = locking.boolean("Conjugate Mean Stress");
  return spec;
}

}  // namespace

MeshSpec parseMesh(const DeckSection& mesh) {
  MeshSpec spec;
  spec.shape_functions = deckValue(kShapeFamilyWords, mesh.word("Shape Functions"));
  if (mesh.has("Exodus File")) {
    spec.exodus_file = mesh.file("Exodus File");
    return spec;
  }
  if (mesh.has("Gmsh File")) {
    spec.gmsh_file = mesh.file("Gmsh File");
    return spec;
  }
  spec.generate = true;
  const DeckSection generate = mesh.section("Generate");
  GeneratorSpec& generator = spec.generator;
  generator.kind = deckValue(kGeneratorWords, generate.word("Type"));
  generator.element = deckValue(kElementWords, generate.word("Element"));
  generator.element_size = generate.real("Element Size (m)");
  generator.lower_left = pair(generate.reals("Lower Left (m)"));
  generator.upper_right = pair(generate.reals("Upper Right (m)"));
  if (generator.kind == GeneratorSpec::Kind::Rectangle) generator.block = generate.text("Block");
  for (const auto& region : generate.entries("Regions"))
    generator.regions.push_back(parseRegion(region));
  if (!generator.regions.empty() && generate.has("Block"))
    throw InputError(generate.pathOf("Block"),
                     "a rectangle with Regions takes its block names from the regions (the rest "
                     "of the box is block `empty`); remove Block or the Regions");
  return spec;
}

MaterialSpec parseMaterial(const DeckSection& material) {
  MaterialSpec spec;
  spec.name = material.name();
  spec.block = material.text("Block");
  spec.points_per_element = static_cast<int>(material.integer("Points Per Element"));
  spec.phase = deckValue(kPhaseModelWords, material.word("Phase Model"));
  spec.porosity = material.real("Porosity");
  spec.solid_density = material.real("Solid Density (kg/m3)");
  spec.solid = parseSolid(material.section("Solid"));
  const bool wet = spec.phase != PhaseModel::Dry;
  if (wet) {
    spec.mass_balance = deckValue(kMassBalanceWords, material.word("Mass Balance"));
    spec.liquid = parseLiquid(material.section("Liquid"));
    spec.conductivity = parseConductivity(material.section("Conductivity"), spec.liquid);
  }
  if (spec.phase == PhaseModel::Unsaturated) {
    spec.retention = parseRetention(material.section("Retention"));
    spec.tension_cracks = deckValue(kTensionCracksWords, material.word("Tension Cracks"));
  }
  spec.initial = parseInitialState(material.section("Initial State"), wet);
  spec.locking = parseLockingMitigation(material.section("Locking Mitigation"));
  return spec;
}

bool hydraulicLoadsAtPoints(const MeshSpec& mesh) {
  return mesh.generate && mesh.generator.kind == GeneratorSpec::Kind::Rectangle &&
         !mesh.generator.regions.empty();
}

StageSpec parseStage(const DeckSection& stage, const MeshSpec& mesh) {
  const ShapeFamily shapes = mesh.shape_functions;
  StageSpec spec;
  spec.name = stage.name();
  spec.solver = deckValue(kSolverWords, stage.word("Solver"));
  spec.duration = stage.real("Duration (s)");
  spec.gravity = stage.real("Gravity (m/s2)");
  spec.local_damping = stage.real("Local Damping");
  spec.local_damping_form = stage.word("Local Damping Form") == "dissipative"
                                ? LocalDampingForm::Dissipative
                                : LocalDampingForm::StartOfStep;
  spec.fixity_keeps_relative_velocity =
      stage.word("Liquid At Solid Fixities") == "relative velocity";
  const std::string hydraulic_loads = stage.word("Hydraulic Loads");
  spec.hydraulic_loads_at_points =
      hydraulic_loads == kHydraulicLoadsByMesh
          ? hydraulicLoadsAtPoints(mesh)
          : hydraulic_loads == "at boundary points" || hydraulic_loads == "through the soil";
  spec.hydraulic_heads_through_soil = hydraulic_loads == "through the soil";
  spec.atmosphere_on_free_surfaces = stage.word("Surfaces Without Condition") == "atmosphere";
  spec.interior_liquid_conservative = stage.word("Interior Liquid Balance") == "conservative";
  spec.free_surface_suction_held = stage.word("Free Surface Liquid Pressure") == "suction held";
  // The held surface subtracts pi_i sum_p V grad N_i from the pressure force; the closure
  // subtracts the matching sum_i N_i V / W_i w_i . G_i from the points' divergence. Only
  // together is the force the transpose of the mass balance's divergence (the pairing on
  // which the explicit step's energy rests): held alone went unstable on the Tri3 levee
  // at 0.1 m (doc/verification.md, "The air's pull held").
  if (spec.free_surface_suction_held && !spec.interior_liquid_conservative)
    throw InputError(stage.pathOf("Free Surface Liquid Pressure"),
                     "'suction held' needs 'Interior Liquid Balance: conservative' in the same "
                     "stage (alone it breaks the pairing of the liquid's pressure force with the "
                     "point mass balance, and went unstable on the Tri3 levee)");
  spec.mass_scaling = stage.real("Mass Scaling");
  const std::string transfer = stage.word("Velocity Transfer");
  spec.transfer = transfer == kTransferByShapeFunctions ? transferForShapes(shapes)
                                                        : deckValue(kTransferSchemeWords, transfer);
  if (spec.transfer != TransferScheme::Flip)
    for (const char* blend : {"Solid PIC Fraction", "Liquid PIC Fraction"})
      if (stage.has(blend))
        throw InputError(stage.pathOf(blend),
                         std::string("blends a PIC update into FLIP, but this stage's transfer "
                                     "is ") +
                             deckWord(kTransferSchemeWords, spec.transfer) + " (the default on " +
                             deckWord(kShapeFamilyWords, shapes) +
                             " shape functions); set 'Velocity Transfer: FLIP' or remove the key");
  if (spec.transfer == TransferScheme::Xpic) {
    spec.xpic.order = static_cast<int>(stage.integer("XPIC Order"));
    const bool chebyshev = stage.word("XPIC Polynomial") == "Chebyshev";
    if (!chebyshev && spec.xpic.order > 8)
      throw InputError(stage.pathOf("XPIC Order"),
                       "the binomial series takes at most 8 terms (its alternating "
                       "coefficients, up to C(m, m/2), lose digits beyond); got " +
                           std::to_string(spec.xpic.order) +
                           ": use 'XPIC Polynomial: Chebyshev' for more passes");
    spec.xpic.lower_eigenvalue = chebyshev ? stage.real("XPIC Lower Eigenvalue") : 0.0;
  }
  // (FLIP or APIC: the schema's condition) a share per second or per step, not both
  for (const char* phase : {"Solid", "Liquid"}) {
    const std::string rate = std::string(phase) + " PIC Rate (1/s)";
    const std::string fraction = std::string(phase) + " PIC Fraction";
    if (stage.has(rate) && stage.has(fraction))
      throw InputError(stage.pathOf(rate),
                       "sets the share per second, '" + fraction + "' per step: give one of them");
  }
  if (stage.has("Solid PIC Rate (1/s)")) spec.solid_pic_rate = stage.real("Solid PIC Rate (1/s)");
  if (stage.has("Liquid PIC Rate (1/s)"))
    spec.liquid_pic_rate = stage.real("Liquid PIC Rate (1/s)");
  spec.solid_pic_fraction = stage.real("Solid PIC Fraction");
  spec.liquid_pic_fraction = stage.real("Liquid PIC Fraction");
  spec.hold_liquid_pressure =
      spec.solver == SolverKind::QuasiStatic && stage.word("Liquid Pressure") == "held";
  spec.implicit_drag = stage.word("Liquid Drag") == "implicit";
  spec.output_interval = stage.real("Output Interval (s)");
  spec.reset_displacements = stage.boolean("Reset Displacements");
  spec.time_step = parseTimeStep(stage.section("Time Step"));
  if (spec.implicit_drag && spec.time_step.automatic && !spec.hold_liquid_pressure) {
    // The drag no longer bounds the step; the explicit pressure diffusion still does, and of
    // the wave criteria only the saturated undrained one stayed below the empirical
    // critical step on the V5 sets (doc/stability.md, "Implicit drag").
    bool parabolic = false, undrained = false;
    for (CriterionKind kind : spec.time_step.criteria) {
      parabolic =
          parabolic || kind == CriterionKind::Consolidation || kind == CriterionKind::Infiltration;
      undrained = undrained || kind == CriterionKind::CflUndrained;
    }
    if (!parabolic || !undrained)
      throw InputError("Stages/" + spec.name + "/Time Step/Criteria",
                       "with 'Liquid Drag: implicit' expected 'cfl undrained' and "
                       "'consolidation' or 'infiltration' among the criteria (the drag no "
                       "longer bounds the step; the undrained wave and the explicit pressure "
                       "diffusion still do)");
  }
  for (const auto& boundary : stage.entries("Boundary Conditions"))
    spec.boundaries.push_back(parseBoundary(boundary));
  parseStageAdditions(stage, spec);  // issue P4 (and P12's Hand Back At Rest)
  if (spec.solver == SolverKind::ImplicitSeepage || spec.hand_back.enabled)
    spec.seepage = parseImplicitSeepage(stage.section("Implicit Seepage"));
  else if (stage.has("Implicit Seepage"))
    throw InputError("Stages/" + spec.name + "/Implicit Seepage",
                     "in an explicit stage only with Hand Back At Rest (the settings of the "
                     "stage's implicit rest)");
  parseFactorOfSafetyHandOver(stage, spec);  // issue P13
  parseStrengthReduction(stage, spec);       // issue P13
  headThroughSoil(spec);                     // refused here, before any stage runs
  return spec;
}

OutputSpec parseOutput(const DeckSection& output) {
  OutputSpec spec;
  spec.directory = output.text("Directory");
  spec.name = output.text("Name");
  const DeckSection checkpoint = output.section("Checkpoint");  // issue P8
  spec.checkpoint.every_steps = checkpoint.integer("Every Steps");
  spec.checkpoint.wall_interval = 60.0 * checkpoint.real("Wall Interval (min)");  // min -> s
  return spec;
}

}  // namespace argine::input_detail

namespace argine {

int headThroughSoil(const StageSpec& stage) {
  if (!stage.hydraulic_heads_through_soil) return -1;
  std::vector<int> heads;
  for (std::size_t c = 0; c < stage.boundaries.size(); ++c)
    if (stage.boundaries[c].kind == BoundaryKind::TotalHead) heads.push_back(static_cast<int>(c));
  if (heads.size() != 1)
    throw InputError("Stages/" + stage.name + "/Hydraulic Loads",
                     "'through the soil' applies one total head condition's pressure over the "
                     "soil; the stage has " +
                         std::to_string(heads.size()) + " (use 'at boundary points' for several)");
  const BoundarySpec& head = stage.boundaries[heads[0]];
  if (head.hydraulic.above == AboveLevel::ConstantPressure && head.hydraulic.pressure_above != 0)
    throw InputError(
        "Stages/" + stage.name + "/Boundary Conditions/" + head.name + "/Pressure Above Level (Pa)",
        "with 'Hydraulic Loads: through the soil' the pressure above the level "
        "must be 0 (or use Above Level: seepage face or linear suction): a "
        "pressure that jumps at the level would load the soil inside");
  return heads[0];
}

}  // namespace argine
