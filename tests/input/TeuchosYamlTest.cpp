// What the deck reader relies on in Teuchos 13.2 YAML, checked so a Trilinos upgrade that
// changes it fails here first.
#include <Teuchos_Array.hpp>

#include "DeckTestSupport.hpp"

namespace argine::test {

TEST(TeuchosYaml, TopLevelMapBecomesTheListItself) {
  // updateParametersFromYamlFile fills the given list with the keys inside `argine:` and
  // drops the name `argine`; the reader parses the text instead, to check that name.
  const auto directory = testDirectory();
  const std::string path = writeFile(directory, "deck.yaml", "anything:\n  Title: x\n");
  Teuchos::ParameterList list("mine");
  Teuchos::updateParametersFromYamlFile(path, Teuchos::ptr(&list));
  EXPECT_TRUE(list.isParameter("Title"));
  EXPECT_FALSE(list.isParameter("anything"));
  EXPECT_EQ(yaml("argine:\n  Title: x\n")->name(), "argine");
}

TEST(TeuchosYaml, KeepsInsertionOrder) {
  const auto list = yaml("argine:\n  zeta: 1\n  alpha: {a: 1}\n  mid: 3\n");
  std::vector<std::string> names;
  for (auto it = list->begin(); it != list->end(); ++it) names.push_back(list->name(it));
  EXPECT_EQ(names, (std::vector<std::string>{"zeta", "alpha", "mid"}));
}

TEST(TeuchosYaml, ValueTypes) {
  const auto list = yaml(
      "argine:\n  int: 3600\n  real: 1.0e-3\n  nan: .nan\n  flag: yes\n  reals: [1, 2.5]\n"
      "  ints: [1, 2]\n  words: [cfl dry, consolidation]\n  empty:\n");
  EXPECT_TRUE(list->getEntry("int").isType<int>());  // hence ints are accepted as reals
  EXPECT_TRUE(list->getEntry("real").isType<double>());
  EXPECT_TRUE(list->getEntry("nan").isType<std::string>());  // hence the NaN check on text
  EXPECT_TRUE(list->getEntry("flag").isType<bool>());
  EXPECT_TRUE(list->getEntry("reals").isType<Teuchos::Array<double>>());
  EXPECT_TRUE(list->getEntry("ints").isType<Teuchos::Array<int>>());
  EXPECT_TRUE(list->getEntry("words").isType<Teuchos::Array<std::string>>());
  EXPECT_TRUE(list->isSublist("empty"));  // `Key:` with nothing is an empty sublist
}

}  // namespace argine::test
