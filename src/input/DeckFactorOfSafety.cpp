// Issue P13: the deck's `Factor Of Safety` section and the stages' hand-over key, parsed and
// cross-checked.
#include <cmath>

#include "DeckParts.hpp"
#include "ValueText.hpp"
#include "argine/core/Error.hpp"

namespace argine::input_detail {

namespace {

constexpr Real kRadiansPerDegree = 3.14159265358979323846 / 180.0;

/// A two-number range [low, high] with low < high, or nothing when the key is absent.
std::optional<std::array<Real, 2>> rangeOf(const DeckSection& section, const std::string& key) {
  if (!section.has(key)) return std::nullopt;
  const std::vector<double> values = section.reals(key);
  if (!(values[0] < values[1]))
    throw InputError(section.pathOf(key), "expected [low, high] with low < high, got [" +
                                              formatReal(values[0]) + ", " + formatReal(values[1]) +
                                              "]");
  return std::array<Real, 2>{values[0], values[1]};
}

}  // namespace

FactorOfSafetySpec parseFactorOfSafety(const DeckSection& section, bool present) {
  FactorOfSafetySpec spec;
  spec.enabled = present;
  if (!present) return spec;
  spec.spencer = section.word("Method") == "spencer";
  spec.centre_x = rangeOf(section, "Centre X (m)");
  spec.centre_y = rangeOf(section, "Centre Y (m)");
  spec.tangent_y = rangeOf(section, "Tangent Y (m)");
  spec.mass_x_range = rangeOf(section, "Mass X Range (m)");
  spec.grid_count = static_cast<int>(section.integer("Grid Count"));
  spec.refinements = static_cast<int>(section.integer("Refinements"));
  spec.search_starts = static_cast<int>(section.integer("Search Starts"));
  spec.slices = static_cast<int>(section.integer("Slices"));
  spec.min_depth = section.real("Minimum Depth (m)");
  const std::string suction = section.word("Suction Strength");
  spec.suction = suction == "vanapalli"  ? SuctionStrength::Vanapalli
                 : suction == "fredlund" ? SuctionStrength::Fredlund
                 : suction == "none"     ? SuctionStrength::None
                                         : SuctionStrength::SolidModel;
  if (spec.suction == SuctionStrength::Fredlund)
    spec.suction_friction_angle = section.real("Suction Friction Angle (deg)") * kRadiansPerDegree;
  if (section.has("Ground Surface (m)")) {
    spec.ground_surface = vertexPairs(section, "Ground Surface (m)");
    if (spec.ground_surface.size() < 2)
      throw InputError(section.pathOf("Ground Surface (m)"),
                       "expected at least two (x, y) vertices, got one");
  }
  spec.cell_size = section.real("Cell Size (m)");
  spec.slice_table = section.boolean("Slice Table");
  return spec;
}

void parseFactorOfSafetyHandOver(const DeckSection& stage_section, StageSpec& stage) {
  const std::string key = "Hand Over Below Factor Of Safety";
  if (stage_section.has(key)) stage.hand_over_below_factor_of_safety = stage_section.real(key);
}

void checkFactorOfSafety(const Deck& deck) {
  if (deck.factor_of_safety.enabled) return;
  for (const StageSpec& stage : deck.stages)
    if (stage.hand_over_below_factor_of_safety > 0)
      throw InputError("Stages/" + stage.name + "/Hand Over Below Factor Of Safety",
                       "needs the deck section `Factor Of Safety` (how the factor of safety is "
                       "computed), which is missing");
}

}  // namespace argine::input_detail
