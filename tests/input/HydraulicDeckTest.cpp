// [Input] The keys of the hydraulic conditions on the moving boundary (total head, pressure
// series, infiltration, seepage face): zones, time series sources, their errors.
#include <gtest/gtest.h>

#include "DeckTestSupport.hpp"
#include "argine/input/Deck.hpp"

namespace argine {
namespace {

using test::expectDeckError;
using test::kBaseDeck;
using test::parseText;

/// The base deck with `conditions` (YAML lines under Boundary Conditions) added.
std::string withConditions(const std::string& conditions) {
  return kBaseDeck + conditions;
}

TEST(HydraulicDeck, ConditionsFillZoneSeriesAndOptions) {
  const Deck deck = parseText(withConditions(R"(        river:
          Type: total head
          Zone: {Type: half-plane, Point (m): [8.0, 0.0], Inside Direction: [-1.0, 0.0]}
          Total Head Table: [0, 0.2, 150, 0.85]
          Above Level: linear suction
        pond:
          Type: pressure series
          Side Set: top
          Pressure Table: [0, 0.0, 10, 2000.0]
          Time Origin: simulation start
        rain:
          Type: infiltration
          Zone: {Type: polyline band, Vertices (m): [0, 1, 4, 1, 6, 0], Width (m): 0.1}
          Flux (m/s): -2.0e-7
          Ponding: true
        face:
          Type: seepage face
          Zone: {Type: box, Lower Left (m): [1, 0], Upper Right (m): [2, 1]}
        still:
          Type: total head
          Side Set: top
          Total Head (m): 1.5
)"));
  const auto& b = deck.stages[0].boundaries;
  ASSERT_EQ(b.size(), 6u);
  EXPECT_EQ(b[1].kind, BoundaryKind::TotalHead);
  EXPECT_TRUE(b[1].hydraulic.on_zone);
  EXPECT_EQ(b[1].hydraulic.zone.kind, ZoneSpec::Kind::HalfPlane);
  EXPECT_DOUBLE_EQ(b[1].hydraulic.zone.point[0], 8.0);
  EXPECT_DOUBLE_EQ(b[1].hydraulic.zone.direction[0], -1.0);
  EXPECT_EQ(b[1].hydraulic.series.source, TimeSeriesSpec::Source::Table);
  EXPECT_EQ(b[1].hydraulic.series.pairs, (std::vector<Real>{0, 0.2, 150, 0.85}));
  EXPECT_EQ(b[1].hydraulic.series.where, "Stages/load/Boundary Conditions/river/Total Head Table");
  EXPECT_EQ(b[1].hydraulic.above, AboveLevel::LinearSuction);
  EXPECT_EQ(b[1].hydraulic.series.origin, TimeOrigin::StageStart);  // default
  EXPECT_DOUBLE_EQ(b[1].hydraulic.liquid_density, 1000.0);          // default
  EXPECT_EQ(b[2].kind, BoundaryKind::PressureSeries);
  EXPECT_FALSE(b[2].hydraulic.on_zone);
  EXPECT_EQ(b[2].side_set, "top");
  EXPECT_EQ(b[2].hydraulic.series.origin, TimeOrigin::SimulationStart);
  EXPECT_EQ(b[3].kind, BoundaryKind::Infiltration);
  EXPECT_EQ(b[3].hydraulic.zone.vertices.size(), 3u);
  EXPECT_DOUBLE_EQ(b[3].hydraulic.zone.width, 0.1);
  EXPECT_EQ(b[3].hydraulic.series.source, TimeSeriesSpec::Source::Constant);
  EXPECT_DOUBLE_EQ(b[3].hydraulic.series.value, -2e-7);
  EXPECT_TRUE(b[3].hydraulic.ponding);
  EXPECT_EQ(b[4].kind, BoundaryKind::SeepageFace);
  EXPECT_DOUBLE_EQ(b[4].hydraulic.zone.upper_right[1], 1.0);
  EXPECT_EQ(b[5].hydraulic.above, AboveLevel::ConstantPressure);  // default
  EXPECT_DOUBLE_EQ(b[5].hydraulic.pressure_above, 0.0);
  EXPECT_DOUBLE_EQ(b[5].hydraulic.series.value, 1.5);
}

TEST(HydraulicDeck, PressureLinearInXTakesTwoAbscissasAndAnEndSeries) {
  const Deck deck = parseText(withConditions(R"(        bottom:
          Type: pressure series
          Side Set: top
          Pressure Table: [0, 82000.0, 60, 102000.0]
          Linear Between x (m): [0.0, 50.0]
          End Pressure Table: [0, 82000.0]
)"));
  const HydraulicSpec& h = deck.stages[0].boundaries[1].hydraulic;
  EXPECT_TRUE(h.linear_in_x);
  EXPECT_DOUBLE_EQ(h.x_range[0], 0.0);
  EXPECT_DOUBLE_EQ(h.x_range[1], 50.0);
  EXPECT_EQ(h.series.pairs, (std::vector<Real>{0, 82000, 60, 102000}));
  EXPECT_EQ(h.end_series.source, TimeSeriesSpec::Source::Table);
  EXPECT_EQ(h.end_series.pairs, (std::vector<Real>{0, 82000}));
  EXPECT_EQ(h.end_series.where, "Stages/load/Boundary Conditions/bottom/End Pressure Table");
  // Without the key the pressure is uniform.
  const Deck uniform = parseText(withConditions(
      "        bottom: {Type: pressure series, Side Set: top, Pressure Table: [0, 1.0]}\n"));
  EXPECT_FALSE(uniform.stages[0].boundaries[1].hydraulic.linear_in_x);
}

TEST(HydraulicDeck, PressureLinearInXErrorsNameTheKey) {
  const std::string where = "Stages/load/Boundary Conditions/bottom";
  const std::string head =
      "        bottom: {Type: pressure series, Side Set: top, "
      "Pressure Table: [0, 1.0]";
  expectDeckError(withConditions(head + ", End Pressure Table: [0, 2.0]}\n"),
                  where + "/End Pressure Table", "Linear Between x (m)");
  expectDeckError(withConditions(head + ", Linear Between x (m): [0, 50]}\n"),
                  where + "/Linear Between x (m)", "End Pressure Table");
  expectDeckError(withConditions(head + ", Linear Between x (m): [5, 5], "
                                        "End Pressure Table: [0, 2.0]}\n"),
                  where + "/Linear Between x (m)", "x0 < x1");
  expectDeckError(withConditions(head + ", Linear Between x (m): [0, 5, 6], "
                                        "End Pressure Table: [0, 2.0]}\n"),
                  where + "/Linear Between x (m)", "2");
  // The keys belong to a pressure series only.
  expectDeckError(withConditions("        bottom: {Type: total head, Side Set: top, Total Head "
                                 "(m): 1.0, Linear Between x (m): [0, 5]}\n"),
                  where + "/Linear Between x (m)", "only when Type is pressure series");
}

TEST(HydraulicDeck, FileSeriesIsResolvedFromTheDeckDirectory) {
  const auto directory = test::testDirectory();
  const std::string deck_text = withConditions(
      "        river: {Type: total head, Side Set: top, "
      "Total Head File: gauge.csv}\n");
  // a missing file names the key (the reader checks FilePath keys)
  test::writeFile(directory, "deck.yaml", deck_text);
  test::expectInputError([&] { readDeck((directory / "deck.yaml").string()); },
                         "Stages/load/Boundary Conditions/river/Total Head File", "gauge.csv");
  test::writeFile(directory, "gauge.csv", "time, level\n0, 0.2\n150, 0.85\n");
  const std::string deck =
      test::writeFile(directory, "deck.yaml",
                      withConditions("        river: {Type: total head, Side Set: top, "
                                     "Total Head File: gauge.csv}\n"));
  const Deck parsed = readDeck(deck);
  const auto& series = parsed.stages[0].boundaries[1].hydraulic.series;
  EXPECT_EQ(series.source, TimeSeriesSpec::Source::File);
  EXPECT_EQ(series.file, (directory / "gauge.csv").string());
  EXPECT_EQ(series.where, "Stages/load/Boundary Conditions/river/Total Head File");
}

TEST(HydraulicDeck, WhereAndValueAreExactlyOneEach) {
  const std::string where = "Stages/load/Boundary Conditions/river";
  expectDeckError(withConditions("        river: {Type: seepage face}\n"), where, "Side Set");
  expectDeckError(withConditions("        river: {Type: total head, Side Set: top}\n"), where,
                  "Total Head");
  expectDeckError(withConditions("        river: {Type: total head, Side Set: top, "
                                 "Total Head (m): 1, Total Head Table: [0, 1]}\n"),
                  where, "exactly one");
  expectDeckError(withConditions("        river: {Type: infiltration, Side Set: top, "
                                 "Zone: {Type: everywhere}, Flux (m/s): 1e-6}\n"),
                  where, "exactly one");
  expectDeckError(withConditions("        river:\n          Type: seepage face\n"
                                 "          Zone: {Type: polyline band, Vertices (m): [0, 1],"
                                 " Width (m): 0.1}\n"),
                  where + "/Zone/Vertices (m)", "at least 2 vertices");
  expectDeckError(withConditions("        river:\n          Type: seepage face\n"
                                 "          Zone: {Type: half-plane, Point (m): [0, 1],"
                                 " Inside Direction: [0, 0]}\n"),
                  where + "/Zone/Inside Direction", "non-zero");
}

}  // namespace
}  // namespace argine
