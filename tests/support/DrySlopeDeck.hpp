#pragma once
/// @file DrySlopeDeck.hpp
/// The head of a test deck: a dry 2:1 slope 4 m high on a 16 x 9 m section (ACADS 1(a)'s
/// shape at 0.4 scale, c' = 1.2 kPa so that c' / (gamma H) stays as in 1(a) with gamma =
/// 0.6 * 2650 * 9.81 = 15598 N/m3), Tri3 of `element_size` (m), 3 points each, K0 = 0.5 from
/// the K0 procedure; `material_extra` (whole lines, e.g. a Locking Mitigation) goes into the
/// material. The caller appends `  Stages:` and the rest. Bishop's F of the initial state is
/// 1.039 (FactorOfSafetyTest); the factor-of-safety and strength-reduction tests share it.

#include <string>

namespace argine::test_decks {

inline std::string drySlopeDeckHead(const std::string& element_size,
                                    const std::string& material_extra = "") {
  return R"(argine:
  Mesh:
    Generate:
      Type: polygon
      Element: tri3
      Element Size (m): )" +
         element_size + R"(
      Lower Left (m): [0.0, 0.0]
      Upper Right (m): [16.0, 9.0]
      Regions:
        soil: {Vertices (m): [0.0, 0.0, 16.0, 0.0, 16.0, 9.0, 12.0, 9.0, 4.0, 5.0, 0.0, 5.0]}
  Materials:
    soil:
      Block: soil
      Points Per Element: 3
      Phase Model: dry
      Porosity: 0.4
      Solid Density (kg/m3): 2650
      Solid: {Model: Mohr-Coulomb, Young's Modulus (Pa): 1.0e7, Poisson's Ratio: 0.3, Cohesion (Pa): 1200, Friction Angle (deg): 19.6, Dilatancy Angle (deg): 0}
      Initial State: {K0: 0.5}
)" + material_extra +
         R"(  Initialisation: {Method: K0 procedure, Ground Surface (m): [0.0, 5.0, 4.0, 5.0, 12.0, 9.0, 16.0, 9.0]}
)";
}

}  // namespace argine::test_decks
