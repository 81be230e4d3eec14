#pragma once
/// @file CriterionKind.hpp
/// The critical time-step criteria argine implements (see timestep/Criteria.hpp).

namespace argine {

/// Critical time-step criteria (thesis Sec. 7, Table 4.4, Appendix).
enum class CriterionKind {
  CflDry,              ///< Eq. 4.62
  CflUndrained,        ///< Eq. 4.64
  Consolidation,       ///< Eq. 4.61
  Infiltration,        ///< Eq. 4.63
  UnsaturatedLiquid,   ///< Table 4.4 / Appendix (liquid momentum)
  UnsaturatedMixture,  ///< Table 4.4 / Appendix (mixture momentum)
  UnsaturatedCoupled,  ///< Table 4.4 / Appendix (coupled system)
  Mieremet,            ///< Eq. 4.67 (saturated), as Anura3D codes it
  /// Eq. 4.67 with the unsaturated drag q_L = S_L n mu/kappa of Eq. 7.7 in its damping term
  /// (one power of S_L where the Sec. 7.2 adaptation has S_L^2): doc/stability.md (V5).
  MieremetLiquidDrag,
};

}  // namespace argine
