#include "StageOverrides.hpp"

#include <stdexcept>

#include "argine/input/DeckWords.hpp"

namespace argine::verification {

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
  if (!known) throw std::invalid_argument("--transfer: expected FLIP or APIC, got '" + word + "'");
  for (StageSpec& stage : deck.stages)
    if (stage.solver != SolverKind::ImplicitSeepage) stage.transfer = scheme;
}

}  // namespace argine::verification
