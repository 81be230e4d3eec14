// The schema mechanism: ranges, conditions, self-checks, and the generated reference.
#include <fstream>
#include <sstream>

#include "DeckTestSupport.hpp"
#include "argine/input/DeckSchema.hpp"
#include "argine/input/DeckValidator.hpp"

namespace argine::test {

TEST(DeckSchema, RangeTextAndBounds) {
  KeySpec open = KeySpec::real("Porosity", "-", "n").above(0).below(1);
  EXPECT_EQ(open.range.text(), "in (0, 1)");
  EXPECT_FALSE(open.range.contains(0.0));
  EXPECT_TRUE(open.range.contains(0.5));
  EXPECT_FALSE(open.range.contains(1.0));
  KeySpec closed = KeySpec::real("K", "Pa", "k").atLeast(0).atMost(2.2e9);
  EXPECT_EQ(closed.range.text(), "in [0, 2.2e9]");
  EXPECT_TRUE(closed.range.contains(0.0));
  EXPECT_TRUE(closed.range.contains(2.2e9));
  EXPECT_EQ(KeySpec::real("a", "-", "a").atLeast(1).range.text(), ">= 1");
  EXPECT_EQ(KeySpec::real("a", "-", "a").below(0.001).range.text(), "< 0.001");
  EXPECT_EQ(KeySpec::real("a", "deg", "a").atLeast(0).below(90).range.text(), "in [0, 90)");
  EXPECT_EQ(KeySpec::real("a", "Pa", "a").above(-1.5e-7).range.text(), "> -1.5e-7");
  EXPECT_EQ(KeySpec::real("a", "Pa", "a").atMost(101325).range.text(), "<= 101325");
  EXPECT_FALSE(KeySpec::real("a", "-", "a").range.contains(std::nan("")));
}

TEST(DeckSchema, DeckSchemaPassesItsSelfCheck) {
  EXPECT_NO_THROW(checkSchema(deckSchema()));
}

TEST(DeckSchema, SelfCheckCatchesAuthorMistakes) {
  ListSchema unknown_word;
  unknown_word.add(KeySpec::choice("Model", {"a", "b"}, "model").require());
  unknown_word.add(KeySpec::real("x", "-", "x").when("Model", {"c"}));
  EXPECT_THROW(checkSchema(unknown_word), std::logic_error);

  ListSchema bad_default;
  bad_default.add(KeySpec::real("x", "-", "x").above(0).byDefault(0.0));
  EXPECT_THROW(checkSchema(bad_default), std::logic_error);

  ListSchema no_unit;
  no_unit.add(KeySpec::real("x", "", "x"));
  EXPECT_THROW(checkSchema(no_unit), std::logic_error);

  ListSchema twice;
  twice.add(KeySpec::real("x", "-", "x"));
  EXPECT_THROW(twice.add(KeySpec::real("x", "-", "x")), std::logic_error);
}

TEST(DeckSchema, ConditionsReachEnclosingLists) {
  // `Liquid Pressure (Pa)` of `Initial State` depends on the material's `Phase Model`.
  expectDeckError(replaced(kBaseDeck, "Porosity: 0.4",
                           "Phase Model: dry\n      Porosity: 0.4\n      Initial State: "
                           "{Liquid Pressure (Pa): 100}"),
                  "Materials/soil/Initial State/Liquid Pressure (Pa)",
                  "applies only when Phase Model is saturated or unsaturated (here Phase Model "
                  "is dry)");
  ListSchema inner;
  inner.add(KeySpec::real("Depth (m)", "m", "depth").when("Kind", {"deep"}).require());
  ListSchema outer;
  outer.add(KeySpec::choice("Kind", {"deep", "shallow"}, "kind").byDefault(std::string("deep")));
  outer.add(KeySpec::sublist("Inner", inner, "inner"));
  checkSchema(outer);
  auto shallow = yaml("test:\n  Kind: shallow\n  Inner: {Depth (m): 3}\n");
  expectInputError([&] { validateParameters(*shallow, outer, "."); }, "Inner/Depth (m)",
                   "here Kind is shallow");
  auto deep = yaml("test:\n  Inner: {}\n");  // Kind defaults to deep: Depth is required
  expectInputError([&] { validateParameters(*deep, outer, "."); }, "Inner/Depth (m)",
                   "missing required key");
}

TEST(DeckSchema, EveryKeyIsDocumentedInTheReference) {
  const std::string reference = deckReferenceMarkdown();
  std::vector<const ListSchema*> pending{&deckSchema()};
  int keys = 0;
  while (!pending.empty()) {
    const ListSchema* schema = pending.back();
    pending.pop_back();
    for (const auto& key : schema->keys) {
      ++keys;
      EXPECT_NE(reference.find("| `" + key.name + "` |"), std::string::npos) << key.name;
      if (key.children) pending.push_back(key.children.get());
    }
  }
  EXPECT_GT(keys, 60);
}

TEST(DeckSchema, GeneratedReferenceIsUpToDate) {
  const std::string path = std::string(ARGINE_SOURCE_DIR) + "/doc/deck-reference.md";
  std::ifstream file(path);
  std::ostringstream committed;
  committed << file.rdbuf();
  EXPECT_TRUE(committed.str() == deckReferenceMarkdown())
      << path << " is stale or missing: run `argine schema > doc/deck-reference.md`";
}

}  // namespace argine::test
