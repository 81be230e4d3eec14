#pragma once
/// @file DeckWords.hpp
/// The words a deck uses for each enumerated choice (`Phase Model: unsaturated`,
/// `Solver: implicit seepage`, ...), in one table per enum. The schema lists the allowed
/// words from these tables and the reader maps words back to enums through them, so a word
/// is spelled in exactly one place. Logs and error messages can name values the same way.

#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "argine/input/Deck.hpp"

namespace argine {

/// One deck word and the enum value it stands for.
template <class Enum>
struct DeckWord {
  const char* word;  ///< as written in the deck (matched case-insensitively)
  Enum value;        ///< what it means
};

inline constexpr DeckWord<PhaseModel> kPhaseModelWords[] = {
    {"dry", PhaseModel::Dry},
    {"saturated", PhaseModel::Saturated},
    {"unsaturated", PhaseModel::Unsaturated},
};

inline constexpr DeckWord<MassBalanceForm> kMassBalanceWords[] = {
    {"complete", MassBalanceForm::Complete},
    {"simplified", MassBalanceForm::Simplified},
};

inline constexpr DeckWord<TensionCracks> kTensionCracksWords[] = {
    {"pore space", TensionCracks::PoreSpace},
    {"air-filled", TensionCracks::AirFilled},
};

inline constexpr DeckWord<SolidModel> kSolidModelWords[] = {
    {"linear elastic", SolidModel::LinearElastic},
    {"Mohr-Coulomb", SolidModel::MohrCoulomb},
    {"suction Mohr-Coulomb", SolidModel::SuctionMohrCoulomb},
};

inline constexpr DeckWord<IncrementAveraging> kIncrementAveragingWords[] = {
    {"none", IncrementAveraging::None},
    {"element", IncrementAveraging::Element},
    {"nodal", IncrementAveraging::Nodal},
};

inline constexpr DeckWord<IncrementAveraging> kSeepagePatchWords[] = {
    {"element", IncrementAveraging::Element},
    {"nodal", IncrementAveraging::Nodal},
};

inline constexpr DeckWord<RetentionModel> kRetentionModelWords[] = {
    {"linear", RetentionModel::Linear},
    {"van Genuchten", RetentionModel::VanGenuchten},
    {"Gardner", RetentionModel::Gardner},
};

inline constexpr DeckWord<ConductivityModel> kConductivityModelWords[] = {
    {"constant", ConductivityModel::Constant},
    {"Hillel", ConductivityModel::Hillel},
    {"Mualem", ConductivityModel::Mualem},
    {"Gardner", ConductivityModel::Gardner},
};

inline constexpr DeckWord<SolverKind> kSolverWords[] = {
    {"explicit", SolverKind::Explicit},
    {"fixed skeleton", SolverKind::FixedSkeleton},
    {"quasi-static", SolverKind::QuasiStatic},
    {"implicit seepage", SolverKind::ImplicitSeepage},
};

inline constexpr DeckWord<StrengthReductionCriterion> kStrengthReductionCriterionWords[] = {
    {"non-convergence", StrengthReductionCriterion::NonConvergence},
    {"accelerating displacement", StrengthReductionCriterion::AcceleratingDisplacement},
    {"either", StrengthReductionCriterion::Either},
    {"continuing displacement", StrengthReductionCriterion::ContinuingDisplacement},
};

inline constexpr DeckWord<ShapeFamily> kShapeFamilyWords[] = {
    {"linear", ShapeFamily::Linear},
    {"GIMP", ShapeFamily::Gimp},
    {"B-spline", ShapeFamily::BSpline},
};

inline constexpr DeckWord<TransferScheme> kTransferSchemeWords[] = {
    {"FLIP", TransferScheme::Flip},
    {"APIC", TransferScheme::Apic},
    {"TPIC", TransferScheme::Tpic},
    {"XPIC", TransferScheme::Xpic},
};
/// The `Velocity Transfer` word (and default) that leaves the choice to the mesh's shape
/// functions (transferForShapes).
inline constexpr const char* kTransferByShapeFunctions = "by shape functions";
/// The `Hydraulic Loads` word (and default) that leaves the choice to the mesh
/// (hydraulicLoadsAtPoints in input/DeckParts).
inline constexpr const char* kHydraulicLoadsByMesh = "by mesh";

inline constexpr DeckWord<CriterionKind> kCriterionWords[] = {
    {"cfl dry", CriterionKind::CflDry},
    {"cfl undrained", CriterionKind::CflUndrained},
    {"consolidation", CriterionKind::Consolidation},
    {"infiltration", CriterionKind::Infiltration},
    {"unsaturated liquid", CriterionKind::UnsaturatedLiquid},
    {"unsaturated mixture", CriterionKind::UnsaturatedMixture},
    {"unsaturated coupled", CriterionKind::UnsaturatedCoupled},
    {"mieremet", CriterionKind::Mieremet},
    {"mieremet liquid drag", CriterionKind::MieremetLiquidDrag},
};

inline constexpr DeckWord<BoundaryKind> kBoundaryWords[] = {
    {"solid fixity", BoundaryKind::SolidFixity},
    {"impermeable", BoundaryKind::LiquidFixity},
    {"traction", BoundaryKind::Traction},
    {"liquid pressure", BoundaryKind::LiquidPressure},
    {"total head", BoundaryKind::TotalHead},
    {"pressure series", BoundaryKind::PressureSeries},
    {"infiltration", BoundaryKind::Infiltration},
    {"seepage face", BoundaryKind::SeepageFace},
    {"frictional wall", BoundaryKind::FrictionalWall},
    {"side walls", BoundaryKind::SideWalls},
};

inline constexpr DeckWord<ZoneSpec::Kind> kZoneWords[] = {
    {"everywhere", ZoneSpec::Kind::Everywhere},
    {"half-plane", ZoneSpec::Kind::HalfPlane},
    {"box", ZoneSpec::Kind::Box},
    {"polyline band", ZoneSpec::Kind::PolylineBand},
};

inline constexpr DeckWord<AboveLevel> kAboveLevelWords[] = {
    {"constant pressure", AboveLevel::ConstantPressure},
    {"linear suction", AboveLevel::LinearSuction},
    {"seepage face", AboveLevel::SeepageFace},
};

inline constexpr DeckWord<TimeOrigin> kTimeOriginWords[] = {
    {"stage start", TimeOrigin::StageStart},
    {"simulation start", TimeOrigin::SimulationStart},
};

inline constexpr DeckWord<ElementType> kElementWords[] = {
    {"tri3", ElementType::Tri3},
    {"quad4", ElementType::Quad4},
};

inline constexpr DeckWord<GeneratorSpec::Kind> kGeneratorWords[] = {
    {"rectangle", GeneratorSpec::Kind::Rectangle},
    {"polygon", GeneratorSpec::Kind::Polygon},
};

/// Directions of a solid fixity: which velocity components are held at zero.
struct FixedDirections {
  bool x;  ///< x component fixed
  bool y;  ///< y component fixed
};
inline constexpr DeckWord<FixedDirections> kDirectionWords[] = {
    {"x", {true, false}},
    {"y", {false, true}},
    {"both", {true, true}},
};

/// Time-step modes: automatic (from the criteria) or a fixed step.
inline constexpr DeckWord<bool> kTimeStepModeWords[] = {
    {"automatic", true},
    {"fixed", false},
};

// ---- issue P4: initialisation and probes ----
inline constexpr DeckWord<InitialisationSpec::Method> kInitialisationWords[] = {
    {"uniform", InitialisationSpec::Method::Uniform},
    {"K0 procedure", InitialisationSpec::Method::K0Procedure},
    {"pore pressure", InitialisationSpec::Method::PorePressure},
};

inline constexpr DeckWord<SectionProbeSpec::Kind> kSectionWords[] = {
    {"band", SectionProbeSpec::Kind::Band},
    {"profile", SectionProbeSpec::Kind::Profile},
};
// ---- end of issue P4 words ----

/// All words of a table, in table order (for the schema and messages).
template <class Enum, std::size_t N>
std::vector<std::string> deckWords(const DeckWord<Enum> (&table)[N]) {
  std::vector<std::string> words;
  for (const auto& entry : table) words.emplace_back(entry.word);
  return words;
}

/// The value of a canonical word (as the validated deck holds it). Throws
/// std::logic_error for a word not in the table: validation has already rejected those.
template <class Enum, std::size_t N>
Enum deckValue(const DeckWord<Enum> (&table)[N], const std::string& word) {
  for (const auto& entry : table)
    if (word == entry.word) return entry.value;
  throw std::logic_error("deckValue: '" + word + "' is not a word of this table");
}

/// The word of a value ("cfl undrained"), for logs and messages.
template <class Enum, std::size_t N>
const char* deckWord(const DeckWord<Enum> (&table)[N], Enum value) {
  for (const auto& entry : table)
    if (entry.value == value) return entry.word;
  return "?";
}

}  // namespace argine
