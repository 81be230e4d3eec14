#pragma once
/// @file FactorOfSafetyMonitor.hpp
/// The factor of safety of the current state at every output (P13 items 1 and 4): the
/// material points become a limit-equilibrium section (slopestability/PointSection.hpp: the
/// ground their envelope, weights, p_L and S_L from them), the strength on a slip surface
/// that of the materials at their suction (SlipSurfaceStrength.hpp), and Bishop's simplified
/// method over a grid search of circles gives the critical circle. Each evaluation is a row
/// of <Name>_factor_of_safety.csv and, optionally, the critical circle's slices in
/// <Name>_critical_slices.csv. A stage may end when the factor falls below a threshold
/// (Simulation: `Hand Over Below Factor Of Safety`).

#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "argine/input/Deck.hpp"
#include "argine/output/CsvWriter.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/slopestability/CircleSearch.hpp"
#include "argine/slopestability/PointSection.hpp"

namespace argine {

/// The points' positions, volumes, weights (M_S + M_L) g, p_L, S_L and materials on the host;
/// points that left the mesh (element < 0) are left out.
SectionPoints sectionPointsOf(const MaterialPoints& points, Real gravity);

/// The section of `points` for `spec`: the deck's ground if given, else the envelope; water
/// standing on the ground weighs rho_L g (the first material's liquid).
SlopeSection sectionForFactorOfSafety(const FactorOfSafetySpec& spec, const SectionPoints& points,
                                      const std::vector<MaterialSpec>& materials, Real gravity);

/// The search grid of `spec` on `section`: the deck's ranges, the unset ones from the ground
/// (centre x over its extent, or over the part of it the mass may occupy; centre y from its top to
/// twice the section's height above; tangents from the floor to the top).
CircleSearchGrid searchGridFor(const FactorOfSafetySpec& spec, const SlopeSection& section);

/// Bishop's critical circle of `points` under gravity g for `spec`.
CriticalCircle criticalCircleOf(const FactorOfSafetySpec& spec, const MaterialPoints& points,
                                const std::vector<MaterialSpec>& materials, Real gravity);

class FactorOfSafetyMonitor {
 public:
  /// Opens <directory>/<name>_factor_of_safety.csv (and _critical_slices.csv when the spec
  /// asks for the slice table); `resume_bytes` continues a checkpointed run's files (empty:
  /// new files).
  FactorOfSafetyMonitor(const FactorOfSafetySpec& spec, const std::string& directory,
                        const std::string& name,
                        const std::vector<std::uint64_t>& resume_bytes = {});

  /// Evaluates the state at `time` and writes its rows; returns Bishop's factor of the
  /// critical circle (NaN when no circle is admissible, e.g. without gravity).
  Real evaluate(Real time, const MaterialPoints& points, const std::vector<MaterialSpec>& materials,
                Real gravity);

  const CriticalCircle& last() const { return last_; }
  /// Bytes written to each file so far (for checkpoints).
  std::vector<std::uint64_t> fileBytes() const;

 private:
  FactorOfSafetySpec spec_;
  std::unique_ptr<CsvWriter> history_;
  std::unique_ptr<CsvWriter> slices_;
  CriticalCircle last_;
};

}  // namespace argine
