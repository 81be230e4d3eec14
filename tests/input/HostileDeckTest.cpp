// [Input] Hostile decks (issue P8): NaN and infinity, huge or negative sizes and counts,
// empty sections. Every one must end in an InputError that names the key, never in a crash,
// a silent wrap-around or a run with a wrong value. (The fuzz target fuzz/fuzz_deck_reader
// explores further; these are the cases the issue names, kept as regression tests.)
#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "DeckTestSupport.hpp"

namespace argine {
namespace {

using test::kBaseDeck;
using test::replaced;

struct Edit {
  std::string from, to, where, part;
};

/// As `argine check` reads it: from a file, so YAML the parser refuses is an InputError too.
void expectFileDeckError(const std::string& text, const std::string& where,
                         const std::string& part) {
  const std::string path = test::writeFile(test::testDirectory(), "deck.yaml", text);
  test::expectInputError([&] { readDeck(path); }, where == "FILE" ? path : where, part);
}

void expectEach(const std::vector<Edit>& edits) {
  for (const Edit& edit : edits) {
    SCOPED_TRACE(edit.to);
    expectFileDeckError(replaced(kBaseDeck, edit.from, edit.to), edit.where, edit.part);
  }
}

TEST(HostileDeck, NaNAndInfinityAreRejectedWhereverANumberGoes) {
  const std::string message = "NaN and infinity are not allowed";
  expectEach({
      {"Young's Modulus (Pa): 1.0e7", "Young's Modulus (Pa): .nan",
       "Materials/soil/Solid/Young's Modulus (Pa)", message},
      {"Porosity: 0.4", "Porosity: .inf", "Materials/soil/Porosity", message},
      {"Duration (s): 0.1", "Duration (s): -1.0e999", "Stages/load/Duration (s)", message},
      // YAML's -.inf is not read by Teuchos' parser: an error naming the deck file
      {"Duration (s): 0.1", "Duration (s): -.inf", "FILE", "malformed YAML"},
      {"Element Size (m): 0.1", "Element Size (m): .NaN", "Mesh/Generate/Element Size (m)",
       message},
      {"Upper Right (m): [0.1, 1.0]", "Upper Right (m): [0.1, .inf]",
       "Mesh/Generate/Upper Right (m)", message},
      // a literal too large for a double reads as infinity
      {"Solid Density (kg/m3): 2700", "Solid Density (kg/m3): 1.0e999",
       "Materials/soil/Solid Density (kg/m3)", message},
      // quoted, it is text that names a non-number
      {"Intrinsic Permeability (m2): 1.0e-12", "Intrinsic Permeability (m2): 'nan'",
       "Materials/soil/Conductivity/Intrinsic Permeability (m2)", message},
  });
  // in an inline time series
  expectFileDeckError(kBaseDeck +
                          "        river: {Type: total head, Side Set: top, "
                          "Total Head Table: [0, 1.0, 10, .nan]}\n",
                      "Stages/load/Boundary Conditions/river/Total Head Table", message);
}

TEST(HostileDeck, HugeOrNegativeSizesAndCountsAreRejected) {
  expectEach({
      {"Element Size (m): 0.1", "Element Size (m): -0.1", "Mesh/Generate/Element Size (m)",
       "must be > 0"},
      // 1e-6 m in a 0.1 m x 1 m box: 1e11 elements
      {"Element Size (m): 0.1", "Element Size (m): 1.0e-6", "Mesh/Generate/Element Size (m)",
       "would make about 1e+11 elements; at most 1e+08"},
      // a box of 1e308 m: infinitely many elements, not an overflow
      {"Upper Right (m): [0.1, 1.0]", "Upper Right (m): [1.0e308, 1.0]",
       "Mesh/Generate/Element Size (m)", "elements; at most"},
      {"Duration (s): 0.1", "Duration (s): -5", "Stages/load/Duration (s)", "must be"},
      {"Porosity: 0.4", "Porosity: 0.4\n      Points Per Element: -4",
       "Materials/soil/Points Per Element", "must be one of 1, 3, 4, 6, 9, 12, 16"},
      {"Porosity: 0.4", "Porosity: 0.4\n      Points Per Element: 4000000000000",
       "Materials/soil/Points Per Element", "must be"},
      // counts are ints: 1e12 would wrap around to a small or negative number
      {"Duration (s): 0.1",
       "Duration (s): 0.1\n      Time Step: {Mode: automatic, Update Interval: 1000000000000}",
       "Stages/load/Time Step/Update Interval", "must be an integer between"},
      {"Duration (s): 0.1",
       "Duration (s): 0.1\n      Time Step: {Mode: automatic, Update Interval: -3}",
       "Stages/load/Time Step/Update Interval", "must be >= 1"},
  });
  expectFileDeckError(
      kBaseDeck +
          "  Probes:\n    Sections:\n      s: {Type: profile, From (m): [0.0, 0.0], "
          "To (m): [0.0, 1.0], Width (m): 0.1, Samples: 2000000000}\n",
      "Probes/Sections/s/Samples", "must be");
}

TEST(HostileDeck, EmptySectionsAndBlocksAreRejected) {
  expectEach({
      {"    Generate: {Type: rectangle, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], "
       "Upper Right (m): [0.1, 1.0]}\n",
       "", "Mesh", "Exodus File"},
      {"Solid: {Model: linear elastic, Young's Modulus (Pa): 1.0e7, Poisson's Ratio: 0.0}",
       "Solid: {}", "Materials/soil/Solid/Model", "missing required key"},
      {"Block: soil", "Block: ''", "Materials/soil/Block", "must not be empty"},
  });
  // no materials or no stages at all, written as an empty value or an empty map
  const auto start = kBaseDeck.find("  Materials:");
  const auto stages = kBaseDeck.find("  Stages:");
  const std::string head = kBaseDeck.substr(0, start);
  const std::string materials = kBaseDeck.substr(start, stages - start);
  const std::string stage_block = kBaseDeck.substr(stages);
  expectFileDeckError(head + "  Materials:\n" + stage_block, "Materials", "");
  expectFileDeckError(head + "  Materials: {}\n" + stage_block, "Materials", "");
  expectFileDeckError(head + materials + "  Stages:\n", "Stages", "");
  expectFileDeckError(head + materials + "  Stages: {}\n", "Stages", "");
  // a polygon region without vertices
  expectFileDeckError(
      replaced(kBaseDeck,
               "Generate: {Type: rectangle, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], "
               "Upper Right (m): [0.1, 1.0]}",
               "Generate: {Type: polygon, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], "
               "Upper Right (m): [0.1, 1.0], Regions: {soil: {Vertices (m): []}}}"),
      "FILE", "malformed YAML");
  expectFileDeckError(
      replaced(kBaseDeck,
               "Generate: {Type: rectangle, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], "
               "Upper Right (m): [0.1, 1.0]}",
               "Generate: {Type: polygon, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], "
               "Upper Right (m): [0.1, 1.0], Regions: {soil: {Vertices (m): [0.0, 0.0]}}}"),
      "Mesh/Generate/Regions/soil/Vertices (m)", "");
}

TEST(HostileDeck, EmptyOrTruncatedFilesNameTheFile) {
  const auto directory = test::testDirectory();
  for (const std::string& text :
       {std::string(), std::string("argine:\n"), std::string("argine"),
        std::string("\xff\xfe\x00garbage", 10), kBaseDeck.substr(0, 200)}) {
    const std::string path = test::writeFile(directory, "deck.yaml", text);
    try {
      readDeck(path);
      ADD_FAILURE() << "no InputError for '" << text << "'";
    } catch (const InputError& error) {
      EXPECT_FALSE(error.where().empty()) << error.what();
      EXPECT_GT(std::string(error.what()).size(), error.where().size() + 2) << error.what();
    }
  }
}

}  // namespace
}  // namespace argine
