// [Boundary] Every time series of a deck is read before the run (issue P8): inline tables
// and CSV gauge files whose times do not increase, in any stage, give an InputError naming
// the key (and the file).
#include <gtest/gtest.h>

#include "../input/DeckTestSupport.hpp"
#include "argine/boundary/DeckTimeSeriesCheck.hpp"

namespace argine {
namespace {

/// The base deck plus a second stage `later` whose river condition is `river`.
std::string deckWithLaterStage(const std::string& river) {
  return test::kBaseDeck +
         "    later:\n      Solver: explicit\n      Duration (s): 0.1\n"
         "      Boundary Conditions:\n"
         "        river: {Type: total head, Side Set: top, " +
         river + "}\n";
}

TEST(DeckTimeSeriesCheck, ATableThatDoesNotIncreaseNamesTheKeyAndRow) {
  EXPECT_NO_THROW(
      checkDeckTimeSeries(test::parseText(deckWithLaterStage("Total Head Table: [0, 1, 10, 2]"))));
  // rows (0, 1), (10, 2), (5, 3): the third row goes back in time
  const Deck back = test::parseText(deckWithLaterStage("Total Head Table: [0, 1, 10, 2, 5, 3]"));
  test::expectInputError([&] { checkDeckTimeSeries(back); },
                         "Stages/later/Boundary Conditions/river/Total Head Table",
                         "times must increase strictly: row 3 has t = 5 s after t = 10 s");
  // a repeated time is not increasing either
  const Deck same = test::parseText(deckWithLaterStage("Total Head Table: [0, 1, 0, 2]"));
  test::expectInputError([&] { checkDeckTimeSeries(same); },
                         "Stages/later/Boundary Conditions/river/Total Head Table", "row 2");
}

TEST(DeckTimeSeriesCheck, TheEndSeriesOfAPressureLinearInXIsCheckedToo) {
  const std::string deck = test::kBaseDeck +
                           "    later:\n      Solver: explicit\n      Duration (s): 0.1\n"
                           "      Boundary Conditions:\n"
                           "        bottom: {Type: pressure series, Side Set: top, Pressure "
                           "Table: [0, 1, 10, 2], Linear Between x (m): [0, 1], End Pressure "
                           "Table: [0, 1, 10, 2, 5, 3]}\n";
  test::expectInputError([&] { checkDeckTimeSeries(test::parseText(deck)); },
                         "Stages/later/Boundary Conditions/bottom/End Pressure Table", "row 3");
}

TEST(DeckTimeSeriesCheck, ACsvFileThatDoesNotIncreaseNamesTheKeyAndTheFile) {
  const auto directory = test::testDirectory();
  const std::string csv =
      test::writeFile(directory, "gauge.csv", "time, level\n0, 0.2\n150, 0.85\n100, 0.9\n");
  const std::string deck =
      test::writeFile(directory, "deck.yaml", deckWithLaterStage("Total Head File: gauge.csv"));
  const Deck parsed = readDeck(deck);  // the reader checks only that the file exists
  test::expectInputError([&] { checkDeckTimeSeries(parsed); },
                         "Stages/later/Boundary Conditions/river/Total Head File",
                         "time-series file '" + csv + "': times must increase strictly: row 3");
  // a NaN in the file is not a number
  test::writeFile(directory, "gauge.csv", "time, level\n0, 0.2\nnan, 0.85\n");
  test::expectInputError([&] { checkDeckTimeSeries(parsed); },
                         "Stages/later/Boundary Conditions/river/Total Head File",
                         "line 3: expected two numbers");
}

}  // namespace
}  // namespace argine
