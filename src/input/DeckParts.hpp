#pragma once
// Conversion of validated deck sections into Deck structs (private to the input room).

#include "DeckSection.hpp"
#include "argine/input/Deck.hpp"

namespace argine::input_detail {

/// `Mesh` -> MeshSpec (file paths absolute, polygons counter-clockwise).
MeshSpec parseMesh(const DeckSection& mesh);
/// One entry of `Materials` -> MaterialSpec (degrees -> radians, kappa <-> k_sat).
MaterialSpec parseMaterial(const DeckSection& material);
/// One entry of `Stages` -> StageSpec.
StageSpec parseStage(const DeckSection& stage);
/// `Output` -> OutputSpec.
OutputSpec parseOutput(const DeckSection& output);

// ---- issue P4 ----
/// `Initialisation` -> InitialisationSpec (polylines as vertex pairs).
InitialisationSpec parseInitialisation(const DeckSection& initialisation);
/// `Probes` -> ProbesSpec.
ProbesSpec parseProbes(const DeckSection& probes);
/// A stage's `Relaxation` and `Material Changes` into `stage`.
void parseStageAdditions(const DeckSection& section, StageSpec& stage);
/// Cross-key checks of initialisation, probes and material changes.
void checkStageAdditions(const Deck& deck);
// ---- end of issue P4 ----

/// (P8) `Guards` -> GuardsSpec (DeckGuards.cpp).
GuardsSpec parseGuards(const DeckSection& guards);

/// Throws when two materials name the same block.
void checkOneMaterialPerBlock(const Deck& deck);

/// Cross-key checks of the mesh section (box corners, polygon regions).
void checkMeshSpec(const MeshSpec& mesh);

}  // namespace argine::input_detail
