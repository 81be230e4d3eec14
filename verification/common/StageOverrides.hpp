#pragma once
/// @file StageOverrides.hpp
/// Options a verification driver applies to the stages of its deck, so that one case runs
/// with the schemes a user may choose (the deck as written stays the reference set-up).

#include "CommandLine.hpp"
#include "argine/input/Deck.hpp"

namespace argine::verification {

/// `--transfer FLIP|APIC|TPIC`: the velocity transfer of every explicit, quasi-static and
/// fixed-skeleton stage (TransferScheme). Absent: the deck's own. std::invalid_argument for
/// another word.
void applyTransferOption(const CommandLine& options, Deck& deck);

/// `--shapes linear|GIMP|B-spline`: the deck's generated rectangle becomes a structured quad4
/// grid with that shape family and 4 points per cell. Absent: the deck's own mesh.
/// std::invalid_argument for another word or a deck that does not generate a rectangle.
void applyShapeOption(const CommandLine& options, Deck& deck);

}  // namespace argine::verification
