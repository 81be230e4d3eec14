// Checks of the deck that involve more than one key; per-key rules are in the schema.
#include <cmath>
#include <cstdio>

#include "DeckParts.hpp"
#include "ValueText.hpp"
#include "argine/core/Error.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/input/DeckWords.hpp"

namespace argine {

using input_detail::formatReal;

namespace {
constexpr Real kPi = 3.14159265358979323846;

/// An angle in radians as degrees with 6 digits (30, not 30.000000000000004).
std::string degrees(Real radians) {
  char text[32];
  std::snprintf(text, sizeof text, "%.6g", radians * 180.0 / kPi);
  return text;
}
}  // namespace

namespace input_detail {

namespace {

bool insideBox(const std::array<Real, 2>& point, const GeneratorSpec& generator) {
  for (int d = 0; d < 2; ++d)
    if (point[d] < generator.lower_left[d] || point[d] > generator.upper_right[d]) return false;
  return true;
}

/// A count to 3 digits ("1e+11").
std::string roughly(Real count) {
  char text[32];
  std::snprintf(text, sizeof text, "%.3g", count);
  return text;
}

/// The generator makes about (width / h) (height / h) squares (twice as many triangles). Far
/// more than a run can hold, or than int node numbers reach, is a typo in Element Size (P8).
void checkGeneratedMeshSize(const GeneratorSpec& generator) {
  constexpr Real kMostGeneratedSquares = 1e8;
  const Real h = generator.element_size;
  const Real width = generator.upper_right[0] - generator.lower_left[0];
  const Real height = generator.upper_right[1] - generator.lower_left[1];
  const Real squares = (width / h) * (height / h);
  if (!(squares <= kMostGeneratedSquares))
    throw InputError("Mesh/Generate/Element Size (m)",
                     formatReal(h) + " m in a box of " + formatReal(width) + " m x " +
                         formatReal(height) + " m would make about " + roughly(squares) +
                         " elements; at most " + roughly(kMostGeneratedSquares) +
                         " are allowed (is the size in metres?)");
}

}  // namespace

void checkOneMaterialPerBlock(const Deck& deck) {
  for (std::size_t m = 0; m < deck.materials.size(); ++m)
    for (std::size_t other = 0; other < m; ++other)
      if (deck.materials[other].block == deck.materials[m].block)
        throw InputError("Materials/" + deck.materials[m].name + "/Block",
                         "block '" + deck.materials[m].block + "' already holds material '" +
                             deck.materials[other].name + "'; each block holds one material");
}

void checkMeshSpec(const MeshSpec& mesh) {
  const bool structured = mesh.generate && mesh.generator.kind == GeneratorSpec::Kind::Rectangle &&
                          mesh.generator.element == ElementType::Quad4;
  if (mesh.shape_functions != ShapeFamily::Linear && !structured)
    throw InputError("Mesh/Shape Functions",
                     std::string(deckWord(kShapeFamilyWords, mesh.shape_functions)) +
                         " shape functions need a structured Quad4 grid (Mesh/Generate with "
                         "Type: rectangle and Element: quad4); use linear with " +
                         (mesh.generate ? "this generator" : "a mesh from a file"));
  if (!mesh.generate) return;
  const GeneratorSpec& generator = mesh.generator;
  const char* axes[] = {"x", "y"};
  for (int d = 0; d < 2; ++d)
    if (!(generator.upper_right[d] > generator.lower_left[d]))
      throw InputError("Mesh/Generate/Upper Right (m)",
                       std::string(axes[d]) + " must exceed that of Lower Left (m) (" +
                           formatReal(generator.lower_left[d]) + "), got " +
                           formatReal(generator.upper_right[d]));
  checkGeneratedMeshSize(generator);
  for (const auto& region : generator.regions) {
    const std::string where = "Mesh/Generate/Regions/" + region.block + "/Vertices (m)";
    if (region.block == "empty")
      throw InputError("Mesh/Generate/Regions/empty",
                       "the name 'empty' is reserved for the box outside the regions");
    Real twice_area = 0;
    for (std::size_t i = 0; i < region.vertices.size(); ++i) {
      const auto& a = region.vertices[i];
      const auto& b = region.vertices[(i + 1) % region.vertices.size()];
      twice_area += a[0] * b[1] - b[0] * a[1];
      if (!insideBox(a, generator))
        throw InputError(where, "vertex " + std::to_string(i + 1) + " (" + formatReal(a[0]) + ", " +
                                    formatReal(a[1]) +
                                    ") lies outside the box Lower Left (m) - Upper Right (m)");
    }
    if (!(std::abs(twice_area) > 0)) throw InputError(where, "the polygon has zero area");
  }
}

}  // namespace input_detail

namespace {

/// Averaging Length (m) and Checkerboard Filter: an element average (of either increment) to
/// apply them to, and one length and one filter choice for every material with an element
/// average (they share the patches' sums and their neighbours).
void checkElementAveraging(const Deck& deck) {
  const MaterialSpec* first = nullptr;  // the first material with an element average
  for (const MaterialSpec& material : deck.materials) {
    const LockingMitigationSpec& locking = material.locking;
    const bool element = locking.volumetric_strain == IncrementAveraging::Element ||
                         locking.liquid_pressure == IncrementAveraging::Element;
    const std::string key =
        "Materials/" + material.name + "/Locking Mitigation/Averaging Length (m)";
    if (locking.averaging_length > 0 && !element)
      throw InputError(key,
                       "applies to element averages: needs Volumetric Strain Averaging or "
                       "Liquid Pressure Averaging: element");
    if (locking.checkerboard_filter && !element)
      throw InputError("Materials/" + material.name + "/Locking Mitigation/Checkerboard Filter",
                       "applies to element averages: needs Volumetric Strain Averaging or "
                       "Liquid Pressure Averaging: element");
    if (locking.conjugate_mean_stress && locking.volumetric_strain == IncrementAveraging::None)
      throw InputError("Materials/" + material.name + "/Locking Mitigation/Conjugate Mean Stress",
                       "applies to averages of the volumetric strain: needs Volumetric Strain "
                       "Averaging: element or nodal");
    // The filter maps the cells' checkerboard to zero, so forces conjugate to the filtered
    // strain leave a checkerboard of mean stress and p_L with no force against it (a free
    // mode: V1's p_L error x2.3, cell to cell; 5.9 kPa rms in a slide's p'). The conjugate
    // forces alone keep the checkerboard as low as the filter (doc/theory.md Sec. 3.3.4).
    if (locking.conjugate_mean_stress && locking.checkerboard_filter)
      throw InputError("Materials/" + material.name + "/Locking Mitigation/Conjugate Mean Stress",
                       "cannot be combined with Checkerboard Filter: true (the filter maps the "
                       "cells' checkerboard to zero, so the conjugate forces would leave it "
                       "free); use one of them");
    if (!element) continue;
    if (first == nullptr) {
      first = &material;
    } else if (locking.checkerboard_filter != first->locking.checkerboard_filter) {
      throw InputError("Materials/" + material.name + "/Locking Mitigation/Checkerboard Filter",
                       "must be the same for every material with an element average (material '" +
                           first->name + "' has " +
                           (first->locking.checkerboard_filter ? "true" : "false") + ")");
    } else if (locking.averaging_length != first->locking.averaging_length) {
      throw InputError(key, "must be the same for every material with an element average (" +
                                formatReal(first->locking.averaging_length) + " in material '" +
                                first->name + "'), got " + formatReal(locking.averaging_length));
    }
  }
}

/// Conjugate Mean Stress: one choice for every material averaging its volumetric strain the
/// same way (element or nodal). Their points share the averages' sums, and the forces do the
/// work of the averaged increments only if the mean stress is averaged over the same points as
/// the strain (doc/theory.md Sec. 3.3.4): at a node or cell shared by a conjugate and a
/// non-conjugate material the two averages would differ.
void checkConjugateMeanStress(const Deck& deck) {
  for (const IncrementAveraging mode : {IncrementAveraging::Element, IncrementAveraging::Nodal}) {
    const MaterialSpec* first = nullptr;  // the first material averaging this way
    for (const MaterialSpec& material : deck.materials) {
      if (material.locking.volumetric_strain != mode) continue;
      if (first == nullptr) {
        first = &material;
      } else if (material.locking.conjugate_mean_stress != first->locking.conjugate_mean_stress) {
        throw InputError(
            "Materials/" + material.name + "/Locking Mitigation/Conjugate Mean Stress",
            std::string("must be the same for every material with Volumetric Strain Averaging: ") +
                (mode == IncrementAveraging::Nodal ? "nodal" : "element") +
                " (they share the averages' sums; material '" + first->name + "' has " +
                (first->locking.conjugate_mean_stress ? "true" : "false") + ")");
      }
    }
  }
}

}  // namespace

void checkDeck(const Deck& deck) {
  input_detail::checkMeshSpec(deck.mesh);
  if (deck.materials.empty()) throw InputError("Materials", "needs at least one material");
  if (deck.stages.empty()) throw InputError("Stages", "needs at least one stage");
  input_detail::checkOneMaterialPerBlock(deck);

  for (const MaterialSpec& material : deck.materials) {
    const std::string path = "Materials/" + material.name;
    const RetentionSpec& retention = material.retention;
    if (!(retention.saturation_min < retention.saturation_max))
      throw InputError(path + "/Retention/Maximum Saturation",
                       "must exceed Minimum Saturation (" + formatReal(retention.saturation_min) +
                           "), got " + formatReal(retention.saturation_max));
    const SolidSpec& solid = material.solid;
    if (solid.model != SolidModel::LinearElastic && solid.dilatancy_angle > solid.friction_angle)
      throw InputError(path + "/Solid/Dilatancy Angle (deg)",
                       "must not exceed Friction Angle (deg) (" + degrees(solid.friction_angle) +
                           "), got " + degrees(solid.dilatancy_angle));
  }

  checkElementAveraging(deck);
  checkConjugateMeanStress(deck);
  input_detail::checkStageAdditions(deck);     // issue P4
  input_detail::checkFactorOfSafety(deck);     // issue P13
  input_detail::checkStrengthReduction(deck);  // issue P13

  if (deck.output.name.find('/') != std::string::npos)
    throw InputError("Output/Name", "must be a file stem without '/', got '" + deck.output.name +
                                        "' (use Output/Directory)");
}

}  // namespace argine
