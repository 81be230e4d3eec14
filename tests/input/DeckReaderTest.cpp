// Reading complete decks: every field of Deck, unit conversions, defaults, order, files.
#include <Teuchos_DefaultComm.hpp>

#include "DeckTestSupport.hpp"

namespace argine::test {

namespace {

const std::string kCompleteDeck = R"(argine:
  Title: complete levee
  Mesh:
    Generate:
      Type: polygon
      Element: tri3
      Element Size (m): 0.5
      Lower Left (m): [0.0, 0.0]
      Upper Right (m): [20, 8.0]
      Regions:
        foundation: {Vertices (m): [0.0, 0.0, 20.0, 0.0, 20.0, 2.0, 0.0, 2.0]}
        embankment: {Vertices (m): [2.0, 2.0, 8.0, 6.0, 12.0, 6.0, 18.0, 2.0]}
  Materials:
    embankment:
      Block: embankment
      Points Per Element: 6
      Phase Model: unsaturated
      Porosity: 0.35
      Solid Density (kg/m3): 2650
      Mass Balance: simplified
      Solid:
        Model: suction Mohr-Coulomb
        Young's Modulus (Pa): 2.0e7
        Poisson's Ratio: 0.3
        Cohesion (Pa): 2000
        Friction Angle (deg): 30
        Dilatancy Angle (deg): 5
        Tensile Strength (Pa): 100
        Cohesion Increase Max (Pa): 10000
        Cohesion Suction Rate B: 0.5
        Friction Suction Rate A (deg): 10
        Atmospheric Pressure (Pa): 100000
      Liquid: {Density (kg/m3): 1000, Bulk Modulus (Pa): 8.0e7, Viscosity (Pa s): 1.0e-3}
      Retention: {Model: van Genuchten, Reference Pressure (Pa): 3000, Lambda: 0.7, Minimum Saturation: 0.125, Maximum Saturation: 0.95}
      Conductivity: {Model: Mualem, Saturated Conductivity (m/s): 1.0e-5, Lambda: 0.6}
      Initial State: {Liquid Pressure (Pa): -5000, Vertical Effective Stress (Pa): -10000, K0: 0.5}
    foundation:
      Block: foundation
      Points Per Element: 1
      Porosity: 0.4
      Solid Density (kg/m3): 2700
      Solid: {Model: Mohr-Coulomb, Young's Modulus (Pa): 5.0e7, Poisson's Ratio: 0.25, Cohesion (Pa): 0, Friction Angle (deg): 35}
      Liquid: {Density (kg/m3): 1020, Viscosity (Pa s): 2.0e-3}
      Conductivity: {Model: Hillel, Intrinsic Permeability (m2): 1.0e-11, Exponent: 4}
  Stages:
    initialise:
      Solver: quasi-static
      Duration (s): 10
      Gravity (m/s2): 9.81
      Local Damping: 0.05
      Local Damping Form: dissipative
      Liquid At Solid Fixities: relative velocity
      Hydraulic Loads: at boundary points
      Mass Scaling: 10
      Output Interval (s): 1
      Time Step: {Mode: fixed, Fixed Step (s): 1.0e-4}
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        sides: {Type: solid fixity, Node Set: left, Direction: x}
        sealed: {Type: impermeable, Side Set: bottom}
    flood:
      Solver: explicit
      Duration (s): 60.5
      Gravity (m/s2): 0
      Reset Displacements: true
      Time Step: {Safety Factor: 0.8, Criteria: [cfl undrained, Unsaturated Coupled, mieremet], Update Interval: 10}
      Boundary Conditions:
        river: {Type: liquid pressure, Side Set: riverside, Pressure (Pa): 30000}
        load: {Type: traction, Side Set: crest, Traction (Pa): [0.0, -10000.0]}
        well: {Type: impermeable, Node Set: well}
  Output: {Directory: out, Name: levee}
)";

}  // namespace

TEST(DeckReader, CompleteDeckFillsEveryField) {
  const Deck deck = parseText(kCompleteDeck);
  EXPECT_EQ(deck.title, "complete levee");

  const GeneratorSpec& generator = deck.mesh.generator;
  EXPECT_TRUE(deck.mesh.generate);
  EXPECT_TRUE(deck.mesh.exodus_file.empty());
  EXPECT_EQ(generator.kind, GeneratorSpec::Kind::Polygon);
  EXPECT_EQ(generator.element, ElementType::Tri3);
  EXPECT_EQ(generator.element_size, 0.5);
  EXPECT_EQ(generator.lower_left, (std::array<Real, 2>{0.0, 0.0}));
  EXPECT_EQ(generator.upper_right, (std::array<Real, 2>{20.0, 8.0}));  // 20 given as an int
  ASSERT_EQ(generator.regions.size(), 2u);
  EXPECT_EQ(generator.regions[0].block, "foundation");
  ASSERT_EQ(generator.regions[0].vertices.size(), 4u);
  EXPECT_EQ(generator.regions[0].vertices[1], (std::array<Real, 2>{20.0, 0.0}));
  // The embankment was written clockwise (twice its signed area is
  // 2*6-8*2 + 8*6-12*6 + 12*2-18*6 + 18*2-2*2 = -80): it is stored reversed.
  const std::vector<std::array<Real, 2>> embankment{{18, 2}, {12, 6}, {8, 6}, {2, 2}};
  EXPECT_EQ(generator.regions[1].block, "embankment");
  EXPECT_EQ(generator.regions[1].vertices, embankment);

  ASSERT_EQ(deck.materials.size(), 2u);
  const MaterialSpec& top = deck.materials[0];
  EXPECT_EQ(top.name, "embankment");
  EXPECT_EQ(top.block, "embankment");
  EXPECT_EQ(top.points_per_element, 6);
  EXPECT_EQ(top.phase, PhaseModel::Unsaturated);
  EXPECT_EQ(top.porosity, 0.35);
  EXPECT_EQ(top.solid_density, 2650.0);
  EXPECT_EQ(top.mass_balance, MassBalanceForm::Simplified);
  EXPECT_EQ(top.solid.model, SolidModel::SuctionMohrCoulomb);
  EXPECT_EQ(top.solid.youngs_modulus, 2.0e7);
  EXPECT_EQ(top.solid.poisson_ratio, 0.3);
  EXPECT_EQ(top.solid.cohesion, 2000.0);
  EXPECT_DOUBLE_EQ(top.solid.friction_angle, 0.5235987755982988);    // 30 deg = pi/6
  EXPECT_DOUBLE_EQ(top.solid.dilatancy_angle, 0.08726646259971647);  // 5 deg = pi/36
  EXPECT_EQ(top.solid.tensile_strength, 100.0);
  EXPECT_EQ(top.solid.cohesion_increase_max, 10000.0);
  EXPECT_EQ(top.solid.cohesion_suction_rate, 0.5);
  EXPECT_DOUBLE_EQ(top.solid.friction_suction_rate, 0.17453292519943295);  // 10 deg = pi/18
  EXPECT_EQ(top.solid.atmospheric_pressure, 100000.0);
  EXPECT_EQ(top.liquid.density, 1000.0);
  EXPECT_EQ(top.liquid.bulk_modulus, 8.0e7);
  EXPECT_EQ(top.liquid.viscosity, 1.0e-3);
  EXPECT_EQ(top.retention.model, RetentionModel::VanGenuchten);
  EXPECT_EQ(top.retention.reference_pressure, 3000.0);
  EXPECT_EQ(top.retention.lambda, 0.7);
  EXPECT_EQ(top.retention.saturation_min, 0.125);
  EXPECT_EQ(top.retention.saturation_max, 0.95);
  EXPECT_EQ(top.conductivity.model, ConductivityModel::Mualem);
  EXPECT_EQ(top.conductivity.mualem_lambda, 0.6);
  EXPECT_EQ(top.conductivity.saturated_conductivity, 1.0e-5);
  // kappa = k_sat mu_L / (rho_L g) = 1e-5 * 1e-3 / (1000 * 9.81) = 1.019367991845056e-12 m2
  EXPECT_NEAR(top.conductivity.intrinsic_permeability, 1.019367991845056e-12, 1e-26);
  EXPECT_EQ(top.initial.liquid_pressure, -5000.0);
  EXPECT_EQ(top.initial.vertical_effective_stress, -10000.0);
  EXPECT_EQ(top.initial.earth_pressure_coefficient, 0.5);

  const MaterialSpec& base = deck.materials[1];
  EXPECT_EQ(base.name, "foundation");
  EXPECT_EQ(base.points_per_element, 1);
  EXPECT_EQ(base.phase, PhaseModel::Saturated);  // default
  EXPECT_EQ(base.solid.model, SolidModel::MohrCoulomb);
  EXPECT_DOUBLE_EQ(base.solid.friction_angle, 0.6108652381980153);  // 35 deg
  EXPECT_EQ(base.solid.dilatancy_angle, 0.0);                       // default
  EXPECT_EQ(base.liquid.density, 1020.0);
  EXPECT_EQ(base.liquid.bulk_modulus, 2.2e9);  // default
  EXPECT_EQ(base.conductivity.model, ConductivityModel::Hillel);
  EXPECT_EQ(base.conductivity.hillel_exponent, 4.0);
  EXPECT_EQ(base.conductivity.intrinsic_permeability, 1.0e-11);
  // k_sat = kappa rho_L g / mu_L = 1e-11 * 1020 * 9.81 / 2e-3 = 1e-11 * 5003100 = 5.0031e-5 m/s
  EXPECT_NEAR(base.conductivity.saturated_conductivity, 5.0031e-5, 1e-18);

  ASSERT_EQ(deck.stages.size(), 2u);
  const StageSpec& first = deck.stages[0];
  EXPECT_EQ(first.name, "initialise");
  EXPECT_EQ(first.solver, SolverKind::QuasiStatic);
  EXPECT_EQ(first.duration, 10.0);
  EXPECT_EQ(first.gravity, 9.81);
  EXPECT_EQ(first.local_damping, 0.05);
  EXPECT_EQ(first.local_damping_form, LocalDampingForm::Dissipative);
  EXPECT_TRUE(first.fixity_keeps_relative_velocity);
  EXPECT_TRUE(first.hydraulic_loads_at_points);
  EXPECT_EQ(first.mass_scaling, 10.0);
  EXPECT_EQ(first.output_interval, 1.0);
  EXPECT_FALSE(first.reset_displacements);
  EXPECT_FALSE(first.time_step.automatic);
  EXPECT_EQ(first.time_step.fixed_step, 1.0e-4);
  ASSERT_EQ(first.boundaries.size(), 3u);
  EXPECT_EQ(first.boundaries[0].name, "base");
  EXPECT_EQ(first.boundaries[0].kind, BoundaryKind::SolidFixity);
  EXPECT_EQ(first.boundaries[0].node_set, "bottom");
  EXPECT_TRUE(first.boundaries[0].fix_x);
  EXPECT_TRUE(first.boundaries[0].fix_y);
  EXPECT_TRUE(first.boundaries[1].fix_x);
  EXPECT_FALSE(first.boundaries[1].fix_y);
  EXPECT_EQ(first.boundaries[2].kind, BoundaryKind::LiquidFixity);
  EXPECT_EQ(first.boundaries[2].side_set, "bottom");
  EXPECT_TRUE(first.boundaries[2].node_set.empty());

  const StageSpec& second = deck.stages[1];
  EXPECT_EQ(second.solver, SolverKind::Explicit);
  EXPECT_EQ(second.duration, 60.5);
  EXPECT_EQ(second.gravity, 0.0);
  EXPECT_TRUE(second.reset_displacements);
  EXPECT_TRUE(second.time_step.automatic);
  EXPECT_EQ(second.time_step.safety_factor, 0.8);
  EXPECT_EQ(second.time_step.update_interval, 10);
  const std::vector<CriterionKind> criteria{
      CriterionKind::CflUndrained, CriterionKind::UnsaturatedCoupled, CriterionKind::Mieremet};
  EXPECT_EQ(second.time_step.criteria, criteria);
  ASSERT_EQ(second.boundaries.size(), 3u);
  EXPECT_EQ(second.boundaries[0].kind, BoundaryKind::LiquidPressure);
  EXPECT_EQ(second.boundaries[0].side_set, "riverside");
  EXPECT_EQ(second.boundaries[0].pressure, 30000.0);
  EXPECT_EQ(second.boundaries[1].kind, BoundaryKind::Traction);
  EXPECT_EQ(second.boundaries[1].traction, (std::array<Real, 2>{0.0, -10000.0}));
  EXPECT_EQ(second.boundaries[2].kind, BoundaryKind::LiquidFixity);
  EXPECT_EQ(second.boundaries[2].node_set, "well");

  EXPECT_EQ(deck.output.directory, "out");
  EXPECT_EQ(deck.output.name, "levee");
}

TEST(DeckReader, SchemaDefaultsEqualStructDefaults) {
  // The base deck leaves every optional key out: the schema's defaults must be the ones
  // Deck.hpp documents.
  const Deck deck = parseText(kBaseDeck);
  const MaterialSpec& material = deck.materials[0];
  const MaterialSpec fresh;
  EXPECT_EQ(material.points_per_element, fresh.points_per_element);
  EXPECT_EQ(material.phase, fresh.phase);
  EXPECT_EQ(material.mass_balance, fresh.mass_balance);
  EXPECT_EQ(material.liquid.density, fresh.liquid.density);
  EXPECT_EQ(material.liquid.bulk_modulus, fresh.liquid.bulk_modulus);
  EXPECT_EQ(material.liquid.viscosity, fresh.liquid.viscosity);
  EXPECT_EQ(material.conductivity.model, fresh.conductivity.model);
  EXPECT_EQ(material.initial.liquid_pressure, fresh.initial.liquid_pressure);
  EXPECT_EQ(material.initial.vertical_effective_stress, fresh.initial.vertical_effective_stress);
  EXPECT_EQ(material.initial.earth_pressure_coefficient, fresh.initial.earth_pressure_coefficient);

  const StageSpec& stage = deck.stages[0];
  const StageSpec fresh_stage;
  EXPECT_EQ(stage.gravity, fresh_stage.gravity);
  EXPECT_EQ(stage.local_damping, fresh_stage.local_damping);
  EXPECT_EQ(stage.local_damping_form, LocalDampingForm::StartOfStep);  // the default
  EXPECT_EQ(stage.local_damping_form, fresh_stage.local_damping_form);
  EXPECT_FALSE(stage.fixity_keeps_relative_velocity);  // the default: the thesis
  EXPECT_FALSE(stage.hydraulic_loads_at_points);       // by mesh: a rectangle without Regions
  EXPECT_EQ(stage.mass_scaling, fresh_stage.mass_scaling);
  EXPECT_EQ(stage.output_interval, fresh_stage.output_interval);
  EXPECT_EQ(stage.reset_displacements, fresh_stage.reset_displacements);
  EXPECT_EQ(stage.time_step.automatic, fresh_stage.time_step.automatic);
  EXPECT_EQ(stage.time_step.safety_factor, fresh_stage.time_step.safety_factor);
  EXPECT_EQ(stage.time_step.criteria, fresh_stage.time_step.criteria);
  EXPECT_EQ(stage.time_step.update_interval, fresh_stage.time_step.update_interval);
  EXPECT_EQ(deck.output.directory, OutputSpec().directory);
  EXPECT_EQ(deck.output.name, OutputSpec().name);
  EXPECT_EQ(deck.mesh.generator.element, GeneratorSpec().element);
  EXPECT_EQ(deck.mesh.generator.block, GeneratorSpec().block);

  // Model-specific defaults.
  const Deck models = parseText(replaced(
      replaced(
          kBaseDeck, "Model: linear elastic",
          "Model: suction Mohr-Coulomb, Cohesion (Pa): 0, Friction Angle (deg): 30, Cohesion "
          "Increase Max (Pa): 0, Cohesion Suction Rate B: 0, Friction Suction Rate A (deg): 0"),
      "Conductivity: {", "Conductivity: {Model: Hillel, "));
  const SolidSpec fresh_solid;
  EXPECT_EQ(models.materials[0].solid.dilatancy_angle, fresh_solid.dilatancy_angle);
  EXPECT_EQ(models.materials[0].solid.tensile_strength, fresh_solid.tensile_strength);
  EXPECT_EQ(models.materials[0].solid.atmospheric_pressure, fresh_solid.atmospheric_pressure);
  EXPECT_EQ(models.materials[0].conductivity.hillel_exponent, ConductivitySpec().hillel_exponent);
  const Deck retention = parseText(
      replaced(kBaseDeck, "Porosity: 0.4",
               "Phase Model: unsaturated\n      Retention: {Model: Gardner, Alpha (1/Pa): 1.0e-4}\n"
               "      Porosity: 0.4"));
  EXPECT_EQ(retention.materials[0].retention.saturation_min, RetentionSpec().saturation_min);
  EXPECT_EQ(retention.materials[0].retention.saturation_max, RetentionSpec().saturation_max);
  EXPECT_EQ(retention.materials[0].retention.gardner_alpha, 1.0e-4);
}

TEST(DeckReader, StagesMaterialsAndConditionsKeepDeckOrder) {
  const std::string stages = R"(  Stages:
    zeta: {Solver: explicit, Duration (s): 1}
    alpha: {Solver: implicit seepage, Duration (s): 2}
    mid:
      Solver: fixed skeleton
      Duration (s): 3
      Boundary Conditions:
        z: {Type: impermeable, Side Set: top}
        a: {Type: impermeable, Side Set: bottom}
)";
  const std::string deck = kBaseDeck.substr(0, kBaseDeck.find("  Stages:")) + stages;
  const Deck parsed = parseText(deck);
  ASSERT_EQ(parsed.stages.size(), 3u);
  EXPECT_EQ(parsed.stages[0].name, "zeta");
  EXPECT_EQ(parsed.stages[1].name, "alpha");
  EXPECT_EQ(parsed.stages[2].name, "mid");
  EXPECT_EQ(parsed.stages[1].solver, SolverKind::ImplicitSeepage);
  EXPECT_EQ(parsed.stages[2].solver, SolverKind::FixedSkeleton);
  EXPECT_EQ(parsed.stages[2].duration, 3.0);
  ASSERT_EQ(parsed.stages[2].boundaries.size(), 2u);
  EXPECT_EQ(parsed.stages[2].boundaries[0].name, "z");
  EXPECT_EQ(parsed.stages[2].boundaries[1].name, "a");
  EXPECT_EQ(parseText(kCompleteDeck).materials[0].name, "embankment");  // written first
}

TEST(DeckReader, ReadsAFileAndResolvesPathsFromItsDirectory) {
  const auto directory = testDirectory();
  std::filesystem::create_directories(directory / "meshes");
  writeFile(directory / "meshes", "column.exo", "not really exodus");
  const std::string text =
      replaced(kBaseDeck,
               "Generate: {Type: rectangle, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], "
               "Upper Right (m): [0.1, 1.0]}",
               "Exodus File: meshes/column.exo");
  const std::string path = writeFile(directory, "deck.yaml", text);
  const Deck deck = readDeck(path);
  EXPECT_EQ(deck.path, path);
  EXPECT_TRUE(std::filesystem::path(deck.path).is_absolute());
  EXPECT_FALSE(deck.mesh.generate);
  EXPECT_EQ(deck.mesh.exodus_file, (directory / "meshes" / "column.exo").string());
  EXPECT_EQ(deck.title, "base column");
  // The same over an explicit communicator.
  const Deck again = readDeck(path, *Teuchos::DefaultComm<int>::getComm());
  EXPECT_EQ(again.mesh.exodus_file, deck.mesh.exodus_file);
}

TEST(DeckReader, MalformedYamlNamesTheFileAndTheParserMessage) {
  const auto directory = testDirectory();
  const std::string path =
      writeFile(directory, "broken.yaml", "argine:\n  Title: x\n  Mesh: {Exodus File: [a, b\n");
  expectInputError([&] { readDeck(path); }, path, "malformed YAML: Parser failure at line 4");
  try {
    readDeck(path);
  } catch (const InputError& error) {  // parser internals are left out
    EXPECT_EQ(std::string(error.what()).find("Parser was in state"), std::string::npos);
    EXPECT_EQ(std::string(error.what()).find("Throw number"), std::string::npos);
  }
  const std::string twice = writeFile(directory, "twice.yaml", "argine:\n  Title: x\n  Title: y\n");
  expectInputError([&] { readDeck(twice); }, twice, "Parameter \"Title\" already exists");
}

TEST(DeckReader, DeckMustBeOneArgineMap) {
  const auto directory = testDirectory();
  const std::string path = writeFile(directory, "flat.yaml", "Title: x\nMesh: {Exodus File: a}\n");
  expectInputError([&] { readDeck(path); }, path,
                   "a deck is one YAML map 'argine:' holding all keys; found top-level 'Title', "
                   "'Mesh'");
  const std::string other = writeFile(directory, "other.yaml", "anura:\n  Title: x\n");
  expectInputError([&] { readDeck(other); }, other, "found top-level 'anura'");
}

TEST(DeckReader, MissingDeckFile) {
  const auto path = (testDirectory() / "absent.yaml").string();
  expectInputError([&] { readDeck(path); }, path, "cannot open the deck file");
}

TEST(DeckReader, ReadMeshSpecNeedsOnlyTheMeshSection) {
  const auto directory = testDirectory();
  const std::string path = writeFile(
      directory, "mesh.yaml",
      "argine:\n  Mesh:\n    Generate: {Type: rectangle, Element: tri3, Element Size (m): 0.5, "
      "Lower Left (m): [0, 0], Upper Right (m): [2, 1], Block: clay}\n");
  const MeshSpec mesh = readMeshSpec(path);
  EXPECT_TRUE(mesh.generate);
  EXPECT_EQ(mesh.generator.kind, GeneratorSpec::Kind::Rectangle);
  EXPECT_EQ(mesh.generator.element, ElementType::Tri3);
  EXPECT_EQ(mesh.generator.block, "clay");
  EXPECT_EQ(mesh.generator.upper_right, (std::array<Real, 2>{2.0, 1.0}));
  // ... but that section is validated as usual.
  const std::string bad = writeFile(directory, "bad.yaml",
                                    "argine:\n  Mesh:\n    Generate: {Type: rectangle, Element "
                                    "Size (m): 0.5, Lower Left (m): [0, 0], Upper Right (m): [2, "
                                    "-1]}\n");
  expectInputError([&] { readMeshSpec(bad); }, "Mesh/Generate/Upper Right (m)",
                   "y must exceed that of Lower Left (m) (0), got -1");
}

TEST(DeckReader, TensionCracksOfAnUnsaturatedMaterial) {
  // The pore-space model (the thesis) by default; air-filled by the key; the key belongs to
  // unsaturated materials only.
  const Deck plain = parseText(kCompleteDeck);
  EXPECT_EQ(plain.materials[0].tension_cracks, TensionCracks::PoreSpace);
  EXPECT_EQ(plain.materials[0].tension_cracks, MaterialSpec{}.tension_cracks);
  const std::string unsaturated = "      Phase Model: unsaturated\n";
  const Deck air = parseText(
      replaced(kCompleteDeck, unsaturated, unsaturated + "      Tension Cracks: air-filled\n"));
  EXPECT_EQ(air.materials[0].tension_cracks, TensionCracks::AirFilled);
  expectDeckError(
      replaced(kCompleteDeck, unsaturated, unsaturated + "      Tension Cracks: water\n"),
      "Materials/embankment/Tension Cracks", "pore space");
  expectDeckError(replaced(kCompleteDeck, "      Points Per Element: 1\n",
                           "      Points Per Element: 1\n      Tension Cracks: air-filled\n"),
                  "Materials/foundation/Tension Cracks", "Phase Model is unsaturated");
}

TEST(DeckReader, PolygonRegionsAreChecked) {
  const std::string rectangle =
      "Generate: {Type: rectangle, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], Upper Right "
      "(m): [0.1, 1.0]}";
  const auto polygon = [&](const std::string& vertices) {
    return replaced(kBaseDeck, rectangle,
                    "Generate: {Type: polygon, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], "
                    "Upper Right (m): [1.0, 1.0], Regions: {soil: {Vertices (m): " +
                        vertices + "}}}");
  };
  EXPECT_NO_THROW(parseText(polygon("[0, 0, 1, 0, 0, 1]")));
  const std::string where = "Mesh/Generate/Regions/soil/Vertices (m)";
  expectDeckError(polygon("[0, 0, 1, 0, 0]"), where, "an even count of numbers");
  expectDeckError(polygon("[0, 0, 1, 0]"), where, "at least 3 vertices, got 2");
  expectDeckError(polygon("[0, 0, 1, 0, 0, 1.5]"), where, "vertex 3 (0, 1.5) lies outside the box");
  expectDeckError(polygon("[0, 0, 0.5, 0.5, 1, 1]"), where, "zero area");
  expectDeckError(replaced(polygon("[0, 0, 1, 0, 0, 1]"), "Regions: {soil:", "Regions: {empty:"),
                  "Mesh/Generate/Regions/empty", "the name 'empty' is reserved");
  expectDeckError(
      replaced(polygon("[0, 0, 1, 0, 0, 1]"), "Type: polygon,", "Type: polygon, Block: soil,"),
      "Mesh/Generate/Block", "applies only when Type is rectangle");
}

TEST(DeckReader, RectangleRegionsAreReadAndChecked) {
  const std::string rectangle =
      "Generate: {Type: rectangle, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], Upper Right "
      "(m): [0.1, 1.0]}";
  const auto withRegions = [&](const std::string& extra, const std::string& vertices) {
    return replaced(kBaseDeck, rectangle,
                    "Generate: {Type: rectangle, Element Size (m): 0.1, Lower Left (m): [0.0, "
                    "0.0], Upper Right (m): [1.0, 1.0]" +
                        extra + ", Regions: {soil: {Vertices (m): " + vertices +
                        "}, crest: {Vertices (m): [0, 0.5, 1, 0.5, 1, 1]}}}");
  };
  // Clockwise vertices are stored counter-clockwise; regions keep deck order.
  const Deck deck = parseText(withRegions("", "[0, 0, 0, 0.5, 1, 0.5, 1, 0]"));
  const GeneratorSpec& generator = deck.mesh.generator;
  EXPECT_EQ(generator.kind, GeneratorSpec::Kind::Rectangle);
  ASSERT_EQ(generator.regions.size(), 2u);
  EXPECT_EQ(generator.regions[0].block, "soil");
  EXPECT_EQ(generator.regions[1].block, "crest");
  EXPECT_EQ(generator.regions[0].vertices[0], (std::array<Real, 2>{1.0, 0.0}));
  // the soil's surface cuts through the grid's cells: hydraulic loads through the boundary
  // points unless the stage names the free sides (`Hydraulic Loads: by mesh`)
  EXPECT_TRUE(deck.stages[0].hydraulic_loads_at_points);
  EXPECT_FALSE(
      parseText(replaced(withRegions("", "[0, 0, 0, 0.5, 1, 0.5, 1, 0]"), "Solver: explicit",
                         "Solver: explicit\n      Hydraulic Loads: on free sides"))
          .stages[0]
          .hydraulic_loads_at_points);
  const std::string where = "Mesh/Generate/Regions/soil/Vertices (m)";
  expectDeckError(withRegions("", "[0, 0, 1.2, 0, 0, 0.5]"), where,
                  "vertex 2 (1.2, 0) lies outside the box");
  expectDeckError(withRegions("", "[0, 0, 1, 0]"), where, "at least 3 vertices, got 2");
  expectDeckError(withRegions(", Block: soil", "[0, 0, 1, 0, 0, 0.5]"), "Mesh/Generate/Block",
                  "takes its block names from the regions");
}

}  // namespace argine::test
