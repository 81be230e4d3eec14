#pragma once
/// @file WetColumnDeck.hpp
/// A test deck: a 0.1 x 1 m column of unsaturated soil (Tri3 of 0.1 m, 3 points each; van
/// Genuchten, p_L = -2 kPa) under rain (1e-4 m/s on the top), one explicit stage `settle` of
/// `duration` (s) under gravity with local damping 0.7 and outputs every 0.02 s; `stage_extra`
/// (whole lines) goes into the stage, `output_extra` into Output. It settles within about
/// 0.15 s, so the hand-back tests (HandBackTest, RestartTest) see it come to rest.

#include <string>

namespace argine::test_decks {

/// The deck up to and including `  Stages:` (RestartTest's hybrid deck adds its own stages).
inline std::string wetColumnDeckHead() {
  return R"(argine:
  Title: a wet column under rain
  Mesh:
    Generate: {Type: rectangle, Element: tri3, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], Upper Right (m): [0.1, 1.0], Block: soil}
  Materials:
    soil:
      Block: soil
      Points Per Element: 3
      Phase Model: unsaturated
      Porosity: 0.4
      Solid Density (kg/m3): 2700
      Solid: {Model: linear elastic, Young's Modulus (Pa): 1.0e7, Poisson's Ratio: 0.0}
      Liquid: {Density (kg/m3): 1000, Bulk Modulus (Pa): 1.0e7, Viscosity (Pa s): 1.0e-3}
      Retention: {Model: van genuchten, Reference Pressure (Pa): 3000, Lambda: 0.7, Minimum Saturation: 0.125, Maximum Saturation: 1.0}
      Conductivity: {Model: constant, Intrinsic Permeability (m2): 1.0e-11}
      Initial State: {Liquid Pressure (Pa): -2000, Vertical Effective Stress (Pa): 0.0, K0: 1.0}
  Stages:
)";
}

/// The explicit stage's conditions: the column fixed at its base, rollers on its sides, the
/// rain on its top (whole lines, indented for a stage).
inline std::string wetColumnExplicitConditions() {
  return R"(      Boundary Conditions:
        base: {Type: solid fixity, Node Set: bottom, Direction: both}
        left: {Type: solid fixity, Node Set: left, Direction: x}
        right: {Type: solid fixity, Node Set: right, Direction: x}
        rain: {Type: infiltration, Side Set: top, Flux (m/s): 1.0e-4}
)";
}

inline std::string wetColumnDeck(const std::string& duration, const std::string& stage_extra,
                                 const std::string& output_extra = "") {
  return wetColumnDeckHead() + R"(    settle:
      Solver: explicit
      Duration (s): )" +
         duration + R"(
      Gravity (m/s2): 9.81
      Local Damping: 0.7
      Output Interval (s): 0.02
)" + stage_extra +
         wetColumnExplicitConditions() + R"(  Output:
    Name: column
)" + output_extra;
}

}  // namespace argine::test_decks
