#pragma once
// Helpers of the input tests: YAML strings to parameter lists, decks written to temporary
// files, a valid base deck to break one key at a time, and an InputError matcher.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <Teuchos_DefaultComm.hpp>
#include <Teuchos_ParameterList.hpp>
#include <Teuchos_YamlParameterListCoreHelpers.hpp>

#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"

namespace argine::test {

/// A small valid deck: one saturated linear elastic column, one stage.
inline const std::string kBaseDeck = R"(argine:
  Title: base column
  Mesh:
    Generate: {Type: rectangle, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], Upper Right (m): [0.1, 1.0]}
  Materials:
    soil:
      Block: soil
      Porosity: 0.4
      Solid Density (kg/m3): 2700
      Solid: {Model: linear elastic, Young's Modulus (Pa): 1.0e7, Poisson's Ratio: 0.0}
      Conductivity: {Intrinsic Permeability (m2): 1.0e-12}
  Stages:
    load:
      Solver: explicit
      Duration (s): 0.1
      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
)";

/// `text` with the first `from` replaced by `to` (the test fails if `from` is absent).
inline std::string replaced(std::string text, const std::string& from, const std::string& to) {
  const auto at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' not in the deck";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

/// The YAML text as Teuchos reads it.
inline Teuchos::RCP<Teuchos::ParameterList> yaml(const std::string& text) {
  return Teuchos::getParametersFromYamlString(text);
}

/// A fresh directory for one test's files (one per MPI rank: tests may run on several).
inline std::filesystem::path testDirectory() {
  const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
  const int rank = Teuchos::DefaultComm<int>::getComm()->getRank();
  const auto directory =
      std::filesystem::path(::testing::TempDir()) / "argine_input" /
      (std::string(info->test_suite_name()) + "." + info->name() + ".rank" + std::to_string(rank));
  std::filesystem::remove_all(directory);
  std::filesystem::create_directories(directory);
  return directory;
}

/// Writes `text` to `directory/name` and returns the path.
inline std::string writeFile(const std::filesystem::path& directory, const std::string& name,
                             const std::string& text) {
  const auto path = directory / name;
  std::ofstream(path) << text;
  return path.string();
}

/// Parses a deck given as YAML text (file keys relative to `deck_path`'s directory).
inline Deck parseText(const std::string& text, const std::string& deck_path = "") {
  return parseDeck(*yaml(text), deck_path);
}

/// Runs `action`, expects an InputError at `where` whose message contains `part`.
template <class Action>
void expectInputError(Action action, const std::string& where, const std::string& part) {
  try {
    action();
    ADD_FAILURE() << "no InputError (expected at " << where << ")";
  } catch (const InputError& error) {
    EXPECT_EQ(error.where(), where) << error.what();
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos)
        << "message: " << error.what() << "\nexpected to contain: " << part;
  }
}

/// Expects parsing `text` to fail at `where` with a message containing `part`.
inline void expectDeckError(const std::string& text, const std::string& where,
                            const std::string& part) {
  expectInputError([&] { parseText(text); }, where, part);
}

}  // namespace argine::test
