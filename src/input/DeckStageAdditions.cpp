// Issue P4: the deck's initialisation, probes, stage relaxation and material changes, parsed
// and cross-checked (kept apart from DeckParts.cpp so each concern stays in one file).
#include <cmath>

#include "DeckParts.hpp"
#include "ValueText.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckWords.hpp"

namespace argine::input_detail {

namespace {

constexpr Real kPi = 3.14159265358979323846;

std::array<Real, 2> pairOf(const DeckSection& section, const std::string& key) {
  const std::vector<double> values = section.reals(key);
  return {values[0], values[1]};
}

std::optional<Real> optionalReal(const DeckSection& section, const std::string& key,
                                 Real scale = 1) {
  if (!section.has(key)) return std::nullopt;
  return section.real(key) * scale;
}

bool isMohrCoulomb(SolidModel model) {
  return model == SolidModel::MohrCoulomb || model == SolidModel::SuctionMohrCoulomb;
}

}  // namespace

std::vector<std::array<Real, 2>> vertexPairs(const DeckSection& section, const std::string& key) {
  const std::vector<double> values = section.reals(key);
  const std::string where = section.pathOf(key);
  if (values.empty() || values.size() % 2 != 0)
    throw InputError(where, "expected x, y pairs (an even, non-zero count of numbers), got " +
                                std::to_string(values.size()) + " numbers");
  std::vector<std::array<Real, 2>> vertices;
  for (std::size_t i = 0; i < values.size(); i += 2) {
    if (!vertices.empty() && !(values[i] > vertices.back()[0]))
      throw InputError(where, "x must increase from vertex to vertex; vertex " +
                                  std::to_string(i / 2 + 1) + " has x = " + formatReal(values[i]) +
                                  " after x = " + formatReal(vertices.back()[0]));
    vertices.push_back({values[i], values[i + 1]});
  }
  return vertices;
}

InitialisationSpec parseInitialisation(const DeckSection& initialisation) {
  InitialisationSpec spec;
  spec.method = deckValue(kInitialisationWords, initialisation.word("Method"));
  if (spec.method == InitialisationSpec::Method::Uniform) return spec;
  if (spec.method == InitialisationSpec::Method::K0Procedure)
    spec.ground_surface = vertexPairs(initialisation, "Ground Surface (m)");
  if (initialisation.has("Pore Pressure Table")) {
    const std::string key = "Pore Pressure Table";
    const std::vector<double> values = initialisation.reals(key);
    const std::string where = initialisation.pathOf(key);
    if (values.empty() || values.size() % 2 != 0)
      throw InputError(where, "expected y, p_L pairs (an even, non-zero count of numbers), got " +
                                  std::to_string(values.size()) + " numbers");
    for (std::size_t i = 0; i < values.size(); i += 2) {
      if (!spec.pore_pressure_table.empty() && !(values[i] > spec.pore_pressure_table.back()[0]))
        throw InputError(where, "y must increase from pair to pair; pair " +
                                    std::to_string(i / 2 + 1) +
                                    " has y = " + formatReal(values[i]) +
                                    " after y = " + formatReal(spec.pore_pressure_table.back()[0]));
      spec.pore_pressure_table.push_back({values[i], values[i + 1]});
    }
  }
  if (initialisation.has("Phreatic Surface (m)"))
    spec.phreatic_surface = vertexPairs(initialisation, "Phreatic Surface (m)");
  if (initialisation.has("Maximum Suction (Pa)"))
    spec.max_suction = initialisation.real("Maximum Suction (Pa)");
  return spec;
}

ProbesSpec parseProbes(const DeckSection& probes) {
  ProbesSpec spec;
  spec.interval = probes.real("Interval (s)");
  for (const auto& point : probes.entries("Points"))
    spec.points.push_back(
        PointProbeSpec{point.name(), pairOf(point, "Position (m)"), point.real("Tolerance (m)")});
  for (const auto& section : probes.entries("Sections")) {
    SectionProbeSpec s;
    s.name = section.name();
    s.kind = deckValue(kSectionWords, section.word("Type"));
    s.from = pairOf(section, "From (m)");
    s.to = pairOf(section, "To (m)");
    s.band_width = section.real("Width (m)");
    if (s.kind == SectionProbeSpec::Kind::Profile)
      s.samples = static_cast<int>(section.integer("Samples"));
    if (s.from == s.to)
      throw InputError(section.pathOf("To (m)"),
                       "must differ from From (m): a section is a "
                       "segment of non-zero length");
    spec.sections.push_back(s);
  }
  for (const auto& name : [&] {
         std::vector<std::string> names;
         for (const auto& p : spec.points) names.push_back(p.name);
         for (const auto& s : spec.sections) names.push_back(s.name);
         return names;
       }())
    if (name.find('/') != std::string::npos)
      throw InputError("Probes/" + name, "a probe name becomes part of a file name: no '/'");
  return spec;
}

void parseStageAdditions(const DeckSection& section, StageSpec& stage) {
  if (section.has("Relaxation")) {
    const DeckSection relaxation = section.section("Relaxation");
    stage.relaxation.enabled = true;
    stage.relaxation.kinetic_energy_ratio = relaxation.real("Kinetic Energy Ratio");
    stage.relaxation.window = relaxation.real("Window (s)");
  }
  if (section.has("Hand Back At Rest")) {  // issue P12
    const DeckSection hand_back = section.section("Hand Back At Rest");
    stage.hand_back.enabled = true;
    stage.hand_back.largest_speed = hand_back.real("Largest Speed (m/s)");
    stage.hand_back.window = hand_back.real("Window (s)");
    if (stage.output_interval <= 0 || stage.output_interval >= stage.hand_back.window)
      throw InputError("Stages/" + stage.name + "/Hand Back At Rest/Window (s)",
                       "expected a window longer than the stage's Output Interval (s) (the "
                       "speed is tested at outputs; an output interval is needed)");
  }
  const Real radians = kPi / 180.0;
  for (const auto& change : section.entries("Material Changes")) {
    MaterialChangeSpec spec;
    spec.material = change.name();
    spec.youngs_modulus = optionalReal(change, "Young's Modulus (Pa)");
    spec.poisson_ratio = optionalReal(change, "Poisson's Ratio");
    spec.cohesion = optionalReal(change, "Cohesion (Pa)");
    spec.friction_angle = optionalReal(change, "Friction Angle (deg)", radians);
    spec.dilatancy_angle = optionalReal(change, "Dilatancy Angle (deg)", radians);
    spec.tensile_strength = optionalReal(change, "Tensile Strength (Pa)");
    spec.intrinsic_permeability = optionalReal(change, "Intrinsic Permeability (m2)");
    spec.saturated_conductivity = optionalReal(change, "Saturated Conductivity (m/s)");
    stage.material_changes.push_back(spec);
  }
}

void checkStageAdditions(const Deck& deck) {
  for (const StageSpec& stage : deck.stages) {
    for (const MaterialChangeSpec& change : stage.material_changes) {
      const std::string where = "Stages/" + stage.name + "/Material Changes/" + change.material;
      const MaterialSpec* material = nullptr;
      for (const auto& m : deck.materials)
        if (m.name == change.material) material = &m;
      if (!material) {
        std::string names;
        for (const auto& m : deck.materials) names += (names.empty() ? "" : ", ") + m.name;
        throw InputError(where, "no material named '" + change.material + "'; materials: " + names);
      }
      const bool strength = change.cohesion || change.friction_angle || change.dilatancy_angle ||
                            change.tensile_strength;
      if (strength && !isMohrCoulomb(material->solid.model))
        throw InputError(where,
                         "cohesion, friction, dilatancy and tensile strength belong to "
                         "the Mohr-Coulomb models; material '" +
                             change.material + "' is " +
                             deckWord(kSolidModelWords, material->solid.model));
      if (change.intrinsic_permeability && change.saturated_conductivity)
        throw InputError(where,
                         "give Intrinsic Permeability (m2) or Saturated Conductivity "
                         "(m/s), not both");
      if ((change.intrinsic_permeability || change.saturated_conductivity) &&
          material->phase == PhaseModel::Dry)
        throw InputError(
            where, "material '" + change.material + "' is dry: it has no permeability to change");
    }
  }
}

}  // namespace argine::input_detail
