#pragma once
// Conversion of validated deck sections into Deck structs (private to the input room).

#include "DeckSection.hpp"
#include "argine/input/Deck.hpp"

namespace argine::input_detail {

/// `Mesh` -> MeshSpec (file paths absolute, polygons counter-clockwise).
MeshSpec parseMesh(const DeckSection& mesh);
/// One entry of `Materials` -> MaterialSpec (degrees -> radians, kappa <-> k_sat).
MaterialSpec parseMaterial(const DeckSection& material);
/// One entry of `Stages` -> StageSpec; `mesh` decides what a stage does not name: the
/// transfer by its shape functions (transferForShapes), the hydraulic loads by whether its
/// elements follow the soil's outline (hydraulicLoadsAtPoints).
StageSpec parseStage(const DeckSection& stage, const MeshSpec& mesh);
/// `Hydraulic Loads: by mesh`: at the boundary points where the soil's surface cuts through
/// the cells (a generated rectangle with Regions: the grid stays structured and the regions
/// are seeded inside it), on the free sides where the elements follow the soil's outline.
bool hydraulicLoadsAtPoints(const MeshSpec& mesh);
/// `Output` -> OutputSpec.
OutputSpec parseOutput(const DeckSection& output);

/// The (x, y) pairs of a list key, x strictly increasing; InputError naming the key for an
/// odd or empty list or a non-increasing x (DeckStageAdditions.cpp).
std::vector<std::array<Real, 2>> vertexPairs(const DeckSection& section, const std::string& key);

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

// ---- issue P13 (DeckFactorOfSafety.cpp) ----
/// `Factor Of Safety` -> FactorOfSafetySpec (`present`: the section is in the deck).
FactorOfSafetySpec parseFactorOfSafety(const DeckSection& section, bool present);
/// A stage's `Hand Over Below Factor Of Safety` into `stage`.
void parseFactorOfSafetyHandOver(const DeckSection& stage_section, StageSpec& stage);
/// The hand-over needs the `Factor Of Safety` section.
void checkFactorOfSafety(const Deck& deck);
/// A stage's `Strength Reduction` into `stage` (DeckStrengthReduction.cpp).
void parseStrengthReduction(const DeckSection& stage_section, StageSpec& stage);
/// A strength-reduction stage's needs (Relaxation, a Mohr-Coulomb material) and exclusions.
void checkStrengthReduction(const Deck& deck);

/// Throws when two materials name the same block.
void checkOneMaterialPerBlock(const Deck& deck);

/// Cross-key checks of the mesh section (box corners, polygon regions).
void checkMeshSpec(const MeshSpec& mesh);

}  // namespace argine::input_detail
