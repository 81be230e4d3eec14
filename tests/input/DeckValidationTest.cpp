// One test per kind of input error: each breaks one key of a valid deck and checks the key
// path and the message.
#include <cmath>
#include <limits>

#include "DeckTestSupport.hpp"

namespace argine::test {

TEST(DeckValidation, BaseDeckIsValid) {
  EXPECT_NO_THROW(parseText(kBaseDeck));
}

TEST(DeckValidation, UnknownKeySuggestsTheClosestKey) {
  expectDeckError(replaced(kBaseDeck, "Duration (s): 0.1", "Duraton: 0.1"), "Stages/load/Duraton",
                  "unknown key 'Duraton'; did you mean 'Duration (s)'?");
  // A key given without its unit, or with the wrong unit, is recognised too.
  expectDeckError(replaced(kBaseDeck, "Porosity: 0.4", "Porosity: 0.4\n      Solid Density: 2700"),
                  "Materials/soil/Solid Density", "did you mean 'Solid Density (kg/m3)'?");
}

TEST(DeckValidation, UnknownKeyWithoutCloseMatchListsValidKeys) {
  expectDeckError(replaced(kBaseDeck, "Porosity: 0.4", "Porosity: 0.4\n      Colour: red"),
                  "Materials/soil/Colour",
                  "unknown key 'Colour'; valid keys here: Block, Points Per Element, Phase Model");
}

TEST(DeckValidation, KeyOfAnotherModelIsRejected) {
  expectDeckError(
      replaced(kBaseDeck, "Poisson's Ratio: 0.0}", "Poisson's Ratio: 0.0, Cohesion (Pa): 5}"),
      "Materials/soil/Solid/Cohesion (Pa)",
      "applies only when Model is Mohr-Coulomb or suction Mohr-Coulomb (here Model is "
      "linear elastic)");
  // A dry material has no liquid: its conductivity would be silently ignored.
  expectDeckError(replaced(kBaseDeck, "Porosity: 0.4", "Phase Model: dry\n      Porosity: 0.4"),
                  "Materials/soil/Conductivity", "here Phase Model is dry");
}

TEST(DeckValidation, WrongTypeNamesExpectedAndFound) {
  expectDeckError(replaced(kBaseDeck, "Duration (s): 0.1", "Duration (s): abc"),
                  "Stages/load/Duration (s)", "expected a real number (s), got string 'abc'");
  expectDeckError(replaced(kBaseDeck, "Duration (s): 0.1", "Duration (s): \"0.1\""),
                  "Stages/load/Duration (s)", "got the quoted text '0.1'");
  expectDeckError(
      replaced(kBaseDeck, "Duration (s): 0.1", "Duration (s): 0.1\n      Reset Displacements: 1"),
      "Stages/load/Reset Displacements", "expected true or false, got integer 1");
  expectDeckError(replaced(kBaseDeck, "Porosity: 0.4", "Porosity:"), "Materials/soil/Porosity",
                  "expected a real number, got an empty value");
  expectDeckError(replaced(kBaseDeck,
                           "Solid: {Model: linear elastic, Young's Modulus (Pa): 1.0e7, "
                           "Poisson's Ratio: 0.0}",
                           "Solid: 5"),
                  "Materials/soil/Solid", "expected a sublist of keys, got integer 5");
}

TEST(DeckValidation, MissingRequiredKey) {
  expectDeckError(replaced(kBaseDeck, "      Porosity: 0.4\n", ""), "Materials/soil/Porosity",
                  "missing required key (initial porosity n0");
  expectDeckError(replaced(kBaseDeck, "      Solver: explicit\n", ""), "Stages/load/Solver",
                  "missing required key");
}

TEST(DeckValidation, ValueOutOfRange) {
  expectDeckError(replaced(kBaseDeck, "Porosity: 0.4", "Porosity: 1.2"), "Materials/soil/Porosity",
                  "must be in (0, 1), got 1.2");
  expectDeckError(replaced(kBaseDeck, "Duration (s): 0.1", "Duration (s): -1"),
                  "Stages/load/Duration (s)", "must be > 0 s, got -1");
  expectDeckError(
      replaced(kBaseDeck, "Duration (s): 0.1", "Duration (s): 0.1\n      Mass Scaling: 0.5"),
      "Stages/load/Mass Scaling", "must be >= 1, got 0.5");
}

TEST(DeckValidation, NanAndInfinityAreRejected) {
  // Teuchos YAML keeps ".nan" a string; the message still says what is wrong.
  expectDeckError(replaced(kBaseDeck, "Porosity: 0.4", "Porosity: .nan"), "Materials/soil/Porosity",
                  "NaN and infinity are not allowed, got '.nan'");
  expectDeckError(replaced(kBaseDeck, "Duration (s): 0.1", "Duration (s): .inf"),
                  "Stages/load/Duration (s)", "NaN and infinity are not allowed");
  expectDeckError(replaced(kBaseDeck, "Upper Right (m): [0.1, 1.0]", "Upper Right (m): [0.1, nan]"),
                  "Mesh/Generate/Upper Right (m)", "item 2 ('nan'): NaN and infinity");
  // A list built in code can hold a real NaN.
  auto parameters = yaml(kBaseDeck);
  parameters->sublist("Materials")
      .sublist("soil")
      .set("Porosity", std::numeric_limits<double>::quiet_NaN());
  expectInputError([&] { parseDeck(*parameters, ""); }, "Materials/soil/Porosity",
                   "NaN and infinity are not allowed");
}

TEST(DeckValidation, WordNotAllowedListsWordsAndSuggests) {
  expectDeckError(replaced(kBaseDeck, "Model: linear elastic", "Model: linear elastc"),
                  "Materials/soil/Solid/Model",
                  "'linear elastc' is not allowed; allowed: linear elastic, Mohr-Coulomb, suction "
                  "Mohr-Coulomb; did you mean 'linear elastic'?");
  expectDeckError(replaced(kBaseDeck, "Model: linear elastic", "Model: elastic"),
                  "Materials/soil/Solid/Model", "did you mean 'linear elastic'?");
  // Words are matched ignoring case.
  const Deck deck = parseText(replaced(kBaseDeck, "Solver: explicit", "Solver: Quasi-Static"));
  EXPECT_EQ(deck.stages[0].solver, SolverKind::QuasiStatic);
}

TEST(DeckValidation, CriteriaAreCheckedWordByWord) {
  const std::string fixed = "Duration (s): 0.1\n      Time Step: {Criteria: \"cfl dry, ";
  expectDeckError(replaced(kBaseDeck, "Duration (s): 0.1", fixed + "consolidaton\"}"),
                  "Stages/load/Time Step/Criteria", "did you mean 'consolidation'?");
  expectDeckError(replaced(kBaseDeck, "Duration (s): 0.1", fixed + "cfl\"}"),
                  "Stages/load/Time Step/Criteria",
                  "'cfl' is not allowed; allowed: cfl dry, cfl undrained, consolidation, "
                  "infiltration, unsaturated liquid, unsaturated mixture, unsaturated coupled, "
                  "mieremet, mieremet liquid drag; did you mean 'cfl dry' or 'cfl undrained'?");
  expectDeckError(replaced(kBaseDeck, "Duration (s): 0.1", fixed + "cfl dry\"}"),
                  "Stages/load/Time Step/Criteria", "'cfl dry' is listed twice");
}

TEST(DeckValidation, ImplicitDragNeedsTheUndrainedAndADiffusionCriterion) {
  // Liquid Drag: implicit drops the drag terms of the criteria; the undrained wave and the
  // explicit pressure diffusion must still bound the step (doc/theory.md Sec. 3.1).
  const std::string implicit =
      "Duration (s): 0.1\n      Liquid Drag: implicit\n"
      "      Time Step: {Criteria: \"";
  const std::string why =
      "with 'Liquid Drag: implicit' expected 'cfl undrained' and "
      "'consolidation' or 'infiltration' among the criteria";
  expectDeckError(replaced(kBaseDeck, "Duration (s): 0.1", implicit + "cfl undrained, mieremet\"}"),
                  "Stages/load/Time Step/Criteria", why);
  expectDeckError(replaced(kBaseDeck, "Duration (s): 0.1", implicit + "mieremet, consolidation\"}"),
                  "Stages/load/Time Step/Criteria", why);
  const Deck deck = parseText(
      replaced(kBaseDeck, "Duration (s): 0.1", implicit + "cfl undrained, infiltration\"}"));
  EXPECT_TRUE(deck.stages[0].implicit_drag);
  EXPECT_FALSE(parseText(kBaseDeck).stages[0].implicit_drag);  // the thesis' explicit drag
}

TEST(DeckValidation, HeadThroughTheSoilNeedsOneContinuousTotalHead) {
  // `Hydraulic Loads: through the soil` spreads one head's field over the soil
  // (physics/HeadLoadsThroughSoil.hpp): refused at parse time, before any stage runs.
  const std::string soil = "Duration (s): 0.1\n      Hydraulic Loads: through the soil";
  const std::string base = "        base: {Type: solid fixity, Node Set: bottom, Direction: both}";
  const std::string river =
      "\n        river: {Type: total head, Zone: {Type: everywhere}, Total Head (m): 2.0";
  expectDeckError(replaced(kBaseDeck, "Duration (s): 0.1", soil), "Stages/load/Hydraulic Loads",
                  "'through the soil' applies one total head condition's pressure over the soil; "
                  "the stage has 0");
  const std::string two = replaced(replaced(kBaseDeck, "Duration (s): 0.1", soil), base,
                                   base + river + "}" + replaced(river, "river", "lake") + "}");
  expectDeckError(two, "Stages/load/Hydraulic Loads", "the stage has 2");
  const std::string jump = replaced(replaced(kBaseDeck, "Duration (s): 0.1", soil), base,
                                    base + river + ", Pressure Above Level (Pa): -500}");
  expectDeckError(jump, "Stages/load/Boundary Conditions/river/Pressure Above Level (Pa)",
                  "the pressure above the level must be 0");
  const Deck one = parseText(replaced(replaced(kBaseDeck, "Duration (s): 0.1", soil), base,
                                      base + river + ", Above Level: seepage face}"));
  EXPECT_TRUE(one.stages[0].hydraulic_heads_through_soil);
  EXPECT_TRUE(one.stages[0].hydraulic_loads_at_points);  // other loads at boundary points
  EXPECT_EQ(headThroughSoil(one.stages[0]), 1);          // after the fixity
}

TEST(DeckValidation, MissingFileIsReportedWithTheResolvedPath) {
  const auto directory = testDirectory();
  const std::string deck = replaced(kBaseDeck,
                                    "Generate: {Type: rectangle, Element Size (m): 0.1, Lower Left "
                                    "(m): [0.0, 0.0], Upper Right (m): [0.1, 1.0]}",
                                    "Exodus File: column.exo");
  const std::string deck_path = writeFile(directory, "deck.yaml", deck);
  expectInputError(
      [&] { parseText(deck, deck_path); }, "Mesh/Exodus File",
      "file 'column.exo' not found (looked for " + (directory / "column.exo").string());
  writeFile(directory, "column.exo", "exodus");
  EXPECT_EQ(parseText(deck, deck_path).mesh.exodus_file, (directory / "column.exo").string());
}

TEST(DeckValidation, IntegersAreAcceptedAsReals) {
  const Deck deck = parseText(replaced(kBaseDeck, "Duration (s): 0.1", "Duration (s): 3600"));
  EXPECT_EQ(deck.stages[0].duration, 3600.0);
  EXPECT_EQ(deck.materials[0].solid_density, 2700.0);  // written as the int 2700
}

TEST(DeckValidation, IntegersRejectFractionsAndUnlistedValues) {
  const std::string key = "Porosity: 0.4";
  expectDeckError(replaced(kBaseDeck, key, key + "\n      Points Per Element: 2.5"),
                  "Materials/soil/Points Per Element", "expected an integer, got real number 2.5");
  expectDeckError(replaced(kBaseDeck, key, key + "\n      Points Per Element: 5"),
                  "Materials/soil/Points Per Element",
                  "must be one of 1, 3, 4, 6, 9, 12, 16, got 5");
  // A whole number written as a real is an integer.
  const Deck deck = parseText(replaced(kBaseDeck, key, key + "\n      Points Per Element: 4.0"));
  EXPECT_EQ(deck.materials[0].points_per_element, 4);
  // The 3 x 3 and 4 x 4 quad patterns (whether the mesh's elements have them is checked
  // when the points are seeded).
  for (const int n : {9, 16}) {
    const Deck quads = parseText(
        replaced(kBaseDeck, key, key + "\n      Points Per Element: " + std::to_string(n)));
    EXPECT_EQ(quads.materials[0].points_per_element, n);
  }
}

TEST(DeckValidation, AlternativesNeedExactlyOne) {
  expectDeckError(replaced(kBaseDeck, "  Mesh:\n", "  Mesh:\n    Exodus File: a.exo\n"), "Mesh",
                  "give exactly one of 'Exodus File' or 'Gmsh File' or 'Generate' (found "
                  "'Exodus File' and 'Generate')");
  expectDeckError(replaced(kBaseDeck, "Conductivity: {Intrinsic Permeability (m2): 1.0e-12}",
                           "Conductivity: {Model: constant}"),
                  "Materials/soil/Conductivity",
                  "give exactly one of 'Intrinsic Permeability (m2)' or 'Saturated Conductivity "
                  "(m/s)' (found none)");
}

TEST(DeckValidation, BoundaryConditionsNeedTheirSetAndValues) {
  const std::string base = "base: {Type: solid fixity, Node Set: bottom, Direction: both}";
  const std::string path = "Stages/load/Boundary Conditions/base";
  expectDeckError(replaced(kBaseDeck, base, "base: {Type: solid fixity, Node Set: bottom}"),
                  path + "/Direction", "missing required key");
  expectDeckError(replaced(kBaseDeck, base, "base: {Type: traction, Traction (Pa): [0.0, -1.0]}"),
                  path + "/Side Set", "required when Type is traction or liquid pressure");
  expectDeckError(replaced(kBaseDeck, base, "base: {Type: liquid pressure, Node Set: bottom}"),
                  path + "/Node Set",
                  "applies only when Type is solid fixity or impermeable or frictional wall");
  expectDeckError(replaced(kBaseDeck, base, "base: {Type: impermeable}"), path,
                  "give exactly one of 'Node Set' or 'Side Set' when Type is impermeable");
  expectDeckError(
      replaced(kBaseDeck, base, "base: {Type: traction, Side Set: top, Traction (Pa): [1.0]}"),
      path + "/Traction (Pa)", "expected a list of 2 real numbers (Pa), got a list of 1");
}

TEST(DeckValidation, FixedTimeStepMustBePositive) {
  const std::string key = "Duration (s): 0.1";
  expectDeckError(replaced(kBaseDeck, key, key + "\n      Time Step: {Mode: fixed}"),
                  "Stages/load/Time Step/Fixed Step (s)", "missing required key");
  expectDeckError(
      replaced(kBaseDeck, key, key + "\n      Time Step: {Mode: fixed, Fixed Step (s): 0}"),
      "Stages/load/Time Step/Fixed Step (s)", "must be > 0 s, got 0");
  expectDeckError(replaced(kBaseDeck, key,
                           key + "\n      Time Step: {Mode: fixed, Fixed Step (s): 1e-6, Safety "
                                 "Factor: 0.5}"),
                  "Stages/load/Time Step/Safety Factor", "applies only when Mode is automatic");
}

TEST(DeckValidation, MohrCoulombNeedsStrengthKeys) {
  expectDeckError(replaced(kBaseDeck, "Model: linear elastic", "Model: Mohr-Coulomb"),
                  "Materials/soil/Solid/Cohesion (Pa)", "missing required key");
  EXPECT_NO_THROW(parseText(replaced(kBaseDeck, "Model: linear elastic",
                                     "Model: Mohr-Coulomb, Cohesion (Pa): 1000, Friction Angle "
                                     "(deg): 30")));
}

TEST(DeckValidation, UnsaturatedMaterialNeedsRetention) {
  expectDeckError(
      replaced(kBaseDeck, "Porosity: 0.4", "Phase Model: unsaturated\n      Porosity: 0.4"),
      "Materials/soil/Retention", "required when Phase Model is unsaturated");
}

TEST(DeckValidation, MapEntriesMustBeSublists) {
  expectDeckError(replaced(kBaseDeck, "    soil:\n      Block: soil",
                           "    Block: soil\n    soil:\n      Block: soil"),
                  "Materials/Block",
                  "'Block' is a key of a material: put it inside a named entry, e.g. "
                  "Materials/<name>/Block");
}

TEST(DeckValidation, AtLeastOneStage) {
  const auto at = kBaseDeck.find("  Stages:");
  expectDeckError(kBaseDeck.substr(0, at) + "  Stages:\n", "Stages", "needs at least one stage");
  expectDeckError(kBaseDeck.substr(0, at), "Stages", "missing required key");
}

TEST(DeckValidation, SaturationBoundsMustBeOrdered) {
  const std::string retention =
      "Phase Model: unsaturated\n      Retention: {Model: linear, Slope (1/Pa): 1.0e-6, Minimum "
      "Saturation: 0.6, Maximum Saturation: 0.5}\n      Porosity: 0.4";
  expectDeckError(replaced(kBaseDeck, "Porosity: 0.4", retention),
                  "Materials/soil/Retention/Maximum Saturation",
                  "must exceed Minimum Saturation (0.6), got 0.5");
}

TEST(DeckValidation, DilatancyMustNotExceedFriction) {
  expectDeckError(replaced(kBaseDeck, "Model: linear elastic",
                           "Model: Mohr-Coulomb, Cohesion (Pa): 0, Friction Angle (deg): 30, "
                           "Dilatancy Angle (deg): 35"),
                  "Materials/soil/Solid/Dilatancy Angle (deg)",
                  "must not exceed Friction Angle (deg) (30), got 35");
}

TEST(DeckValidation, OneMaterialPerBlock) {
  const std::string second = "  Stages:";
  const std::string clay =
      "    clay:\n      Block: soil\n      Phase Model: dry\n      Porosity: 0.3\n      Solid "
      "Density (kg/m3): 2650\n      Solid: {Model: linear elastic, Young's Modulus (Pa): 5.0e6, "
      "Poisson's Ratio: 0.3}\n  Stages:";
  expectDeckError(replaced(kBaseDeck, second, clay), "Materials/clay/Block",
                  "block 'soil' already holds material 'soil'");
}

/// A second material, in block clay, that averages its liquid pressure per element (so it
/// shares the element averages' rows with the first); replaces "  Stages:".
const std::string kClayAveragingPressurePerElement =
    "    clay:\n      Block: clay\n      Porosity: 0.3\n      Solid Density (kg/m3): 2650\n"
    "      Solid: {Model: linear elastic, Young's Modulus (Pa): 5.0e6, Poisson's Ratio: 0.3}\n"
    "      Conductivity: {Intrinsic Permeability (m2): 1.0e-12}\n"
    "      Locking Mitigation: {Liquid Pressure Averaging: element}\n  Stages:";

/// The base deck with `Locking Mitigation: {mitigation}` on its material soil.
std::string withLocking(const std::string& mitigation) {
  return replaced(kBaseDeck, "Porosity: 0.4",
                  "Porosity: 0.4\n      Locking Mitigation: {" + mitigation + "}");
}

/// `deck` with the second material kClayAveragingPressurePerElement.
std::string withClay(const std::string& deck) {
  return replaced(deck, "  Stages:", kClayAveragingPressurePerElement);
}

TEST(DeckValidation, AveragingLengthNeedsAnElementAverageAndOneLength) {
  const std::string key = "Materials/soil/Locking Mitigation/Averaging Length (m)";
  expectDeckError(withLocking("Volumetric Strain Averaging: nodal, Averaging Length (m): 0.2"), key,
                  "applies to element averages");
  expectDeckError(withLocking("Volumetric Strain Averaging: element, Averaging Length (m): -0.2"),
                  key, "-0.2");
  const std::string deck =
      withLocking("Volumetric Strain Averaging: element, Averaging Length (m): 0.2");
  EXPECT_NO_THROW(parseText(deck));
  // a second material averaging per element with another length (or none) shares the sums
  expectDeckError(withClay(deck), "Materials/clay/Locking Mitigation/Averaging Length (m)",
                  "must be the same for every material with an element average (0.2 in "
                  "material 'soil'), got 0");
}

TEST(DeckValidation, CheckerboardFilterNeedsAnElementAverageEverywhere) {
  expectDeckError(withLocking("Volumetric Strain Averaging: nodal, Checkerboard Filter: true"),
                  "Materials/soil/Locking Mitigation/Checkerboard Filter",
                  "applies to element averages");
  const std::string deck =
      withLocking("Volumetric Strain Averaging: element, Checkerboard Filter: true");
  EXPECT_NO_THROW(parseText(deck));
  // a second material's element averages share the rows, so the filter too
  expectDeckError(withClay(deck), "Materials/clay/Locking Mitigation/Checkerboard Filter",
                  "must be the same for every material with an element average (material "
                  "'soil' has true)");
}

TEST(DeckValidation, ConjugateMeanStressNeedsAnAverageOfTheStrain) {
  // an average of the pressure alone gives the strain nothing to be conjugate to
  expectDeckError(withLocking("Liquid Pressure Averaging: element, Conjugate Mean Stress: true"),
                  "Materials/soil/Locking Mitigation/Conjugate Mean Stress",
                  "needs Volumetric Strain Averaging: element or nodal");
  expectDeckError(withLocking("Conjugate Mean Stress: true"),
                  "Materials/soil/Locking Mitigation/Conjugate Mean Stress",
                  "needs Volumetric Strain Averaging: element or nodal");
  EXPECT_NO_THROW(
      parseText(withLocking("Volumetric Strain Averaging: element, Conjugate Mean Stress: true")));
  EXPECT_NO_THROW(
      parseText(withLocking("Volumetric Strain Averaging: nodal, Conjugate Mean Stress: true")));
}

TEST(DeckValidation, ConjugateMeanStressRefusesTheCheckerboardFilter) {
  // the filter's null space (the checkerboard) would be a free mode of the conjugate forces
  expectDeckError(withLocking("Volumetric Strain Averaging: element, Checkerboard Filter: true, "
                              "Conjugate Mean Stress: true"),
                  "Materials/soil/Locking Mitigation/Conjugate Mean Stress",
                  "cannot be combined with Checkerboard Filter: true");
  EXPECT_NO_THROW(parseText(withLocking(
      "Volumetric Strain Averaging: element, Checkerboard Filter: false, Conjugate Mean Stress: "
      "true")));
}

TEST(DeckValidation, ConjugateMeanStressIsOneChoiceForMaterialsSharingAnAverage) {
  // A second material, in block clay, averaging its volumetric strain the same way as soil
  // with or without the conjugate forces.
  auto clay = [](const std::string& mode, bool conjugate) {
    return "    clay:\n      Block: clay\n      Phase Model: dry\n      Porosity: 0.3\n"
           "      Solid Density (kg/m3): 2650\n      Solid: {Model: linear elastic, Young's "
           "Modulus (Pa): 5.0e6, Poisson's Ratio: 0.3}\n      Locking Mitigation: {Volumetric "
           "Strain Averaging: " +
           mode + ", Conjugate Mean Stress: " + (conjugate ? "true" : "false") + "}\n  Stages:";
  };
  const std::string key = "Materials/clay/Locking Mitigation/Conjugate Mean Stress";
  for (const std::string mode : {"nodal", "element"}) {
    const std::string soil =
        withLocking("Volumetric Strain Averaging: " + mode + ", Conjugate Mean Stress: true");
    expectDeckError(replaced(soil, "  Stages:", clay(mode, false)), key,
                    "must be the same for every material with Volumetric Strain Averaging: " +
                        mode + " (they share the averages' sums; material 'soil' has true)");
    EXPECT_NO_THROW(parseText(replaced(soil, "  Stages:", clay(mode, true))));
  }
  // averaged another way, the second material shares no sums with the first
  const std::string soil =
      withLocking("Volumetric Strain Averaging: nodal, Conjugate Mean Stress: true");
  EXPECT_NO_THROW(parseText(replaced(soil, "  Stages:", clay("element", false))));
}

TEST(DeckValidation, FirstErrorInDeckOrderIsReported) {
  std::string deck = replaced(kBaseDeck, "Porosity: 0.4", "Porosity: 2");
  deck = replaced(deck, "Element Size (m): 0.1", "Element Size: 0.1");
  expectDeckError(deck, "Mesh/Generate/Element Size", "did you mean 'Element Size (m)'?");
}

}  // namespace argine::test
