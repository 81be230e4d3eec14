// Issue P4 deck sections: Initialisation (K0 procedure), Probes, stage Relaxation and
// Material Changes: values, defaults and the errors of bad input.
#include <cmath>

#include "DeckTestSupport.hpp"

namespace argine::test {

namespace {

const std::string kAdditions = R"(  Initialisation:
    Method: K0 procedure
    Ground Surface (m): [0.0, 1.0, 0.1, 0.9]
    Phreatic Surface (m): [0.0, 0.5, 0.1, 0.5]
    Maximum Suction (Pa): 15000
  Probes:
    Interval (s): 0.01
    Points:
      toe: {Position (m): [0.05, 0.2], Tolerance (m): 0.1}
    Sections:
      axis: {Type: profile, From (m): [0.05, 0.0], To (m): [0.05, 1.0], Width (m): 0.1, Samples: 21}
      band: {Type: band, From (m): [0.0, 0.5], To (m): [0.1, 0.5], Width (m): 0.05}
)";

const std::string kStageAdditions =
    R"(      Relaxation: {Kinetic Energy Ratio: 1.0e-5, Window (s): 0.05}
      Material Changes:
        soil: {Young's Modulus (Pa): 2.0e7, Saturated Conductivity (m/s): 1.0e-5}
)";

std::string deckWithAdditions() {
  return kBaseDeck + kAdditions;
}

std::string deckWithStageAdditions(const std::string& stage) {
  return replaced(kBaseDeck, "      Boundary Conditions:\n",
                  stage + "      Boundary Conditions:\n");
}

TEST(DeckStageAdditions, ReadsInitialisationAndProbes) {
  const Deck deck = parseText(deckWithAdditions());
  const InitialisationSpec& init = deck.initialisation;
  EXPECT_EQ(init.method, InitialisationSpec::Method::K0Procedure);
  ASSERT_EQ(init.ground_surface.size(), 2u);
  EXPECT_EQ(init.ground_surface[1][0], 0.1);
  EXPECT_EQ(init.ground_surface[1][1], 0.9);
  ASSERT_EQ(init.phreatic_surface.size(), 2u);
  EXPECT_EQ(init.phreatic_surface[0][1], 0.5);
  EXPECT_EQ(init.max_suction, 15000);

  const ProbesSpec& probes = deck.probes;
  EXPECT_EQ(probes.interval, 0.01);
  ASSERT_EQ(probes.points.size(), 1u);
  EXPECT_EQ(probes.points[0].name, "toe");
  EXPECT_EQ(probes.points[0].position[1], 0.2);
  EXPECT_EQ(probes.points[0].tolerance, 0.1);
  ASSERT_EQ(probes.sections.size(), 2u);
  EXPECT_EQ(probes.sections[0].kind, SectionProbeSpec::Kind::Profile);
  EXPECT_EQ(probes.sections[0].samples, 21);
  EXPECT_EQ(probes.sections[0].to[1], 1.0);
  EXPECT_EQ(probes.sections[1].kind, SectionProbeSpec::Kind::Band);
  EXPECT_EQ(probes.sections[1].band_width, 0.05);
}

TEST(DeckStageAdditions, DefaultsEqualStructDefaults) {
  const Deck deck = parseText(kBaseDeck);
  EXPECT_EQ(deck.initialisation.method, InitialisationSpec().method);
  EXPECT_TRUE(deck.initialisation.ground_surface.empty());
  EXPECT_TRUE(deck.probes.empty());
  EXPECT_FALSE(deck.stages[0].relaxation.enabled);
  EXPECT_TRUE(deck.stages[0].material_changes.empty());
  // Without a phreatic surface or a cap, K0 keeps "none" (-1) for the cap.
  const Deck k0 = parseText(kBaseDeck +
                            "  Initialisation: {Method: K0 procedure, Ground Surface (m): [0.0, "
                            "1.0]}\n  Probes:\n    Sections:\n      s: {Type: profile, From (m): "
                            "[0.0, 0.0], To (m): [0.0, 1.0], Width (m): 0.1}\n");
  EXPECT_TRUE(k0.initialisation.phreatic_surface.empty());
  EXPECT_EQ(k0.initialisation.max_suction, InitialisationSpec().max_suction);
  EXPECT_EQ(k0.probes.interval, ProbesSpec().interval);
  EXPECT_EQ(k0.probes.sections[0].samples, SectionProbeSpec().samples);
}

TEST(DeckStageAdditions, ReadsRelaxationAndMaterialChanges) {
  const Deck deck = parseText(deckWithStageAdditions(kStageAdditions));
  const StageSpec& stage = deck.stages[0];
  EXPECT_TRUE(stage.relaxation.enabled);
  EXPECT_EQ(stage.relaxation.kinetic_energy_ratio, 1.0e-5);
  EXPECT_EQ(stage.relaxation.window, 0.05);
  ASSERT_EQ(stage.material_changes.size(), 1u);
  const MaterialChangeSpec& change = stage.material_changes[0];
  EXPECT_EQ(change.material, "soil");
  ASSERT_TRUE(change.youngs_modulus.has_value());
  EXPECT_EQ(*change.youngs_modulus, 2.0e7);
  ASSERT_TRUE(change.saturated_conductivity.has_value());
  EXPECT_EQ(*change.saturated_conductivity, 1.0e-5);
  EXPECT_FALSE(change.cohesion.has_value());
  EXPECT_FALSE(change.intrinsic_permeability.has_value());
}

TEST(DeckStageAdditions, LiquidPressureHeldOnlyInQuasiStaticStages) {
  // The drained hand-over stage (Liquid Pressure: held); free by default.
  EXPECT_FALSE(parseText(kBaseDeck).stages[0].hold_liquid_pressure);
  const std::string quasi_static = replaced(kBaseDeck, "Solver: explicit", "Solver: quasi-static");
  EXPECT_FALSE(parseText(quasi_static).stages[0].hold_liquid_pressure);
  const std::string held = replaced(quasi_static, "      Boundary Conditions:\n",
                                    "      Liquid Pressure: held\n      Boundary Conditions:\n");
  EXPECT_TRUE(parseText(held).stages[0].hold_liquid_pressure);
  expectInputError([&] { parseText(replaced(held, "Solver: quasi-static", "Solver: explicit")); },
                   "Stages/load/Liquid Pressure", "applies only when Solver is quasi-static");
  expectInputError(
      [&] { parseText(replaced(held, "Liquid Pressure: held", "Liquid Pressure: on")); },
      "Stages/load/Liquid Pressure", "allowed: free, held");
}

TEST(DeckStageAdditions, SuctionHeldSurfacesNeedTheConservativeInteriorBalance) {
  // `Free Surface Liquid Pressure: suction held` and `Interior Liquid Balance: conservative`
  // pair the pressure force with the point balance; the held surface alone is refused.
  const std::string both = deckWithStageAdditions(
      "      Interior Liquid Balance: conservative\n"
      "      Free Surface Liquid Pressure: suction held\n");
  EXPECT_TRUE(parseText(both).stages[0].free_surface_suction_held);
  EXPECT_TRUE(parseText(both).stages[0].interior_liquid_conservative);
  EXPECT_FALSE(parseText(kBaseDeck).stages[0].free_surface_suction_held);
  expectInputError(
      [&] { parseText(replaced(both, "      Interior Liquid Balance: conservative\n", "")); },
      "Stages/load/Free Surface Liquid Pressure", "needs 'Interior Liquid Balance: conservative'");
}

TEST(DeckStageAdditions, FrictionAngleChangeIsConvertedToRadians) {
  const std::string mohr =
      replaced(kBaseDeck, "Model: linear elastic",
               "Model: Mohr-Coulomb, Cohesion (Pa): 20000, Friction Angle (deg): 30");
  const Deck deck = parseText(replaced(mohr, "      Boundary Conditions:\n",
                                       "      Material Changes:\n        soil: {Cohesion (Pa): "
                                       "2000, Friction Angle (deg): 20}\n      Boundary "
                                       "Conditions:\n"));
  const MaterialChangeSpec& change = deck.stages[0].material_changes[0];
  EXPECT_EQ(*change.cohesion, 2000);
  // 20 deg = 20 pi / 180 = 0.3490658503988659 rad
  EXPECT_NEAR(*change.friction_angle, 0.3490658503988659, 1e-15);
}

TEST(DeckStageAdditions, BadInputNamesTheKey) {
  expectInputError(
      [&] {
        parseText(replaced(deckWithAdditions(), "[0.0, 1.0, 0.1, 0.9]", "[0.1, 1.0, 0.0, 0.9]"));
      },
      "Initialisation/Ground Surface (m)", "x must increase");
  expectInputError(
      [&] { parseText(replaced(deckWithAdditions(), "[0.0, 0.5, 0.1, 0.5]", "[0.0, 0.5, 0.1]")); },
      "Initialisation/Phreatic Surface (m)", "pairs");
  expectInputError(
      [&] { parseText(replaced(deckWithAdditions(), "To (m): [0.1, 0.5]", "To (m): [0.0, 0.5]")); },
      "Probes/Sections/band/To (m)", "must differ");
  expectInputError(
      [&] {
        parseText(deckWithStageAdditions(
            "      Material Changes:\n        clay: {Young's Modulus (Pa): 1.0e7}\n"));
      },
      "Stages/load/Material Changes/clay", "no material named 'clay'");
  expectInputError(
      [&] {
        parseText(
            deckWithStageAdditions("      Material Changes:\n        soil: {Cohesion (Pa): 1}\n"));
      },
      "Stages/load/Material Changes/soil", "Mohr-Coulomb");
  expectInputError(
      [&] {
        parseText(deckWithStageAdditions(
            "      Material Changes:\n        soil: {Intrinsic Permeability (m2): 1.0e-12, "
            "Saturated Conductivity (m/s): 1.0e-5}\n"));
      },
      "Stages/load/Material Changes/soil", "not both");
}

}  // namespace

}  // namespace argine::test
