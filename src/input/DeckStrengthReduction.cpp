// Issue P13 item 3: a stage's `Strength Reduction` section, parsed and cross-checked.
#include "DeckParts.hpp"
#include "ValueText.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckWords.hpp"

namespace argine::input_detail {

void parseStrengthReduction(const DeckSection& stage_section, StageSpec& stage) {
  if (!stage_section.has("Strength Reduction")) return;
  const DeckSection section = stage_section.section("Strength Reduction");
  StrengthReductionSpec& spec = stage.strength_reduction;
  spec.enabled = true;
  spec.initial_factor = section.real("Initial Factor");
  spec.factor_step = section.real("Factor Step");
  spec.tolerance = section.real("Factor Tolerance");
  spec.minimum_factor = section.real("Minimum Factor");
  spec.maximum_factor = section.real("Maximum Factor");
  spec.criterion = deckValue(kStrengthReductionCriterionWords, section.word("Failure Criterion"));
  spec.minimum_displacement = section.real("Minimum Displacement (m)");
  if (!(spec.minimum_factor < spec.maximum_factor))
    throw InputError(section.pathOf("Maximum Factor"),
                     "must exceed Minimum Factor (" + formatReal(spec.minimum_factor) + "), got " +
                         formatReal(spec.maximum_factor));
  if (spec.initial_factor < spec.minimum_factor || spec.initial_factor > spec.maximum_factor)
    throw InputError(section.pathOf("Initial Factor"),
                     "must lie within [Minimum Factor, Maximum Factor] = [" +
                         formatReal(spec.minimum_factor) + ", " + formatReal(spec.maximum_factor) +
                         "], got " + formatReal(spec.initial_factor));
}

void checkStrengthReduction(const Deck& deck) {
  for (const StageSpec& stage : deck.stages) {
    if (!stage.strength_reduction.enabled) continue;
    const std::string where = "Stages/" + stage.name + "/Strength Reduction";
    if (!stage.relaxation.enabled)
      throw InputError(where,
                       "needs the stage's Relaxation (when a trial has come to rest), "
                       "which is missing");
    if (stage.hand_over_below_factor_of_safety > 0)
      throw InputError("Stages/" + stage.name + "/Hand Over Below Factor Of Safety",
                       "has no meaning in a strength-reduction stage (it leaves the state as "
                       "it found it)");
    if (stage.output_interval > 0)
      throw InputError("Stages/" + stage.name + "/Output Interval (s)",
                       "has no meaning in a strength-reduction stage: its trials write "
                       "<Name>_strength_reduction.csv, not the Exodus output");
    if (!stage.material_changes.empty())
      throw InputError("Stages/" + stage.name + "/Material Changes",
                       "not in a strength-reduction stage: change the materials in the stage "
                       "before it");
    bool frictional = false;
    for (const MaterialSpec& material : deck.materials)
      frictional = frictional || material.solid.model == SolidModel::MohrCoulomb ||
                   material.solid.model == SolidModel::SuctionMohrCoulomb;
    if (!frictional)
      throw InputError(where,
                       "needs a Mohr-Coulomb material (Solid/Model: Mohr-Coulomb or "
                       "suction Mohr-Coulomb): nothing else has a strength to reduce");
  }
}

}  // namespace argine::input_detail
