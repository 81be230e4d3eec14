#include "StageOverrides.hpp"

#include <stdexcept>
#include <string>

#include "argine/input/DeckWords.hpp"

namespace argine::verification {

namespace {

/// The listed words of a deck vocabulary, for the message naming what was expected.
template <typename Words>
std::string wordList(const Words& words) {
  std::string list;
  for (const auto& entry : words) list += (list.empty() ? "" : ", ") + std::string(entry.word);
  return list;
}

}  // namespace

void applyTransferOption(const CommandLine& options, Deck& deck) {
  if (!options.has("transfer")) return;
  const std::string word = options.text("transfer", "");
  bool known = false;
  TransferScheme scheme = TransferScheme::Flip;
  for (const auto& entry : kTransferSchemeWords)
    if (word == entry.word) {
      scheme = entry.value;
      known = true;
    }
  if (!known)
    throw std::invalid_argument("--transfer: expected one of " + wordList(kTransferSchemeWords) +
                                ", got '" + word + "'");
  for (StageSpec& stage : deck.stages)
    if (stage.solver != SolverKind::ImplicitSeepage) stage.transfer = scheme;
}

void applyShapeOption(const CommandLine& options, Deck& deck) {
  if (!options.has("shapes")) return;
  const std::string word = options.text("shapes", "");
  bool known = false;
  for (const auto& entry : kShapeFamilyWords)
    if (word == entry.word) {
      deck.mesh.shape_functions = entry.value;
      known = true;
    }
  if (!known)
    throw std::invalid_argument("--shapes: expected one of " + wordList(kShapeFamilyWords) +
                                ", got '" + word + "'");
  if (!deck.mesh.generate || deck.mesh.generator.kind != GeneratorSpec::Kind::Rectangle)
    throw std::invalid_argument("--shapes: the deck must generate a rectangle mesh");
  // The grid families live on structured quad4 grids; 2 x 2 points per cell, the quad4
  // counterpart of the Tri3 decks' 3 points per triangle (6 per square).
  deck.mesh.generator.element = ElementType::Quad4;
  for (auto& material : deck.materials) material.points_per_element = 4;
}

}  // namespace argine::verification
