// Initialisation/Method: pore pressure (P10): p_L of every point hydrostatic from a phreatic
// surface (capped at the maximum suction) or linear in y from a table, with rho_L, S_L, k and
// M_L to match, while the stress stays each material's Initial State; and the deck errors.
// Through the set-up a run uses (readDeck's parser, loadMesh, seedPoints, initialisePoints).
#include <gtest/gtest.h>

#include <Teuchos_YamlParameterListCoreHelpers.hpp>
#include <algorithm>
#include <cmath>
#include <string>

#include "argine/core/Error.hpp"
#include "argine/init/Initialisation.hpp"
#include "argine/input/DeckReader.hpp"
#include "argine/physics/LiquidState.hpp"
#include "argine/physics/MaterialTable.hpp"
#include "argine/points/MaterialPoints.hpp"
#include "argine/simulation/Setup.hpp"

namespace argine {
namespace {

/// A 0.2 m x 1 m unsaturated column (0.1 m quads) with `initialisation` (a YAML flow map).
std::string columnDeck(const std::string& initialisation) {
  return R"(argine:
  Mesh:
    Generate: {Type: rectangle, Element Size (m): 0.1, Lower Left (m): [0.0, 0.0], Upper Right (m): [0.2, 1.0]}
  Materials:
    soil:
      Block: soil
      Points Per Element: 4
      Phase Model: unsaturated
      Porosity: 0.4
      Solid Density (kg/m3): 2700
      Solid: {Model: linear elastic, Young's Modulus (Pa): 1.0e7, Poisson's Ratio: 0.3}
      Liquid: {Density (kg/m3): 1000, Bulk Modulus (Pa): 2.2e9, Viscosity (Pa s): 1.0e-3}
      Retention: {Model: van Genuchten, Reference Pressure (Pa): 3000, Lambda: 0.7, Minimum Saturation: 0.125, Maximum Saturation: 1.0}
      Conductivity: {Model: constant, Saturated Conductivity (m/s): 1.0e-4}
      Initial State: {Liquid Pressure (Pa): -2000, Vertical Effective Stress (Pa): -1500, K0: 0.5}
  Initialisation: )" +
         initialisation + R"(
  Stages:
    wet:
      Solver: fixed skeleton
      Duration (s): 0.01
      Gravity (m/s2): 9.81
)";
}

Deck parse(const std::string& text) {
  return parseDeck(*Teuchos::getParametersFromYamlString(text), "");
}

/// Initialises the deck's points and checks each against expected_pressure(x, y).
template <class Expected>
void expectPorePressures(const std::string& initialisation, Expected expected_pressure) {
  const Deck deck = parse(columnDeck(initialisation));
  const Mesh mesh = loadMesh(deck);
  MaterialPoints points = seedPoints(deck, mesh);
  (void)initialisePoints(deck, mesh, points);
  const MaterialTable table(deck.materials);
  const PointMaterial& material = table.host(0);
  const auto X = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.position);
  const auto P = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.pressure_liquid);
  const auto S = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.saturation);
  const auto M = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.mass_liquid);
  const auto V = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.volume);
  const auto R = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.density_liquid);
  const auto T = Kokkos::create_mirror_view_and_copy(Kokkos::HostSpace(), points.stress_effective);
  ASSERT_GT(points.count, 0);
  for (int p = 0; p < points.count; ++p) {
    const Real expected = expected_pressure(X(p, 0), X(p, 1));
    EXPECT_NEAR(P(p), expected, 1e-9 * std::max<Real>(1, std::fabs(expected))) << "y " << X(p, 1);
    const Real s = saturationAndConductivity(material, P(p)).saturation;
    EXPECT_DOUBLE_EQ(S(p), s);
    EXPECT_DOUBLE_EQ(R(p), liquidDensity(material.liquid, P(p)));
    EXPECT_NEAR(M(p), 0.4 * s * R(p) * V(p), 1e-12 * M(p));
    // the stress is the material's Initial State, not a K0 profile
    EXPECT_DOUBLE_EQ(T(p, YY), -1500);
    EXPECT_DOUBLE_EQ(T(p, XX), -750);
  }
}

TEST(PorePressureInitialisation, HydrostaticFromThePhreaticSurface) {
  // water table at 0.6 m: p_L = 1000 x 9.81 x (0.6 - y), suction above it
  expectPorePressures("{Method: pore pressure, Phreatic Surface (m): [0.0, 0.6, 0.2, 0.6]}",
                      [](Real, Real y) { return 1000 * 9.81 * (0.6 - y); });
  // a sloping surface from 0.4 to 0.8 m, suction capped at 2 kPa
  expectPorePressures(
      "{Method: pore pressure, Phreatic Surface (m): [0.0, 0.4, 0.2, 0.8], Maximum Suction (Pa): "
      "2000}",
      [](Real x, Real y) { return std::max<Real>(1000 * 9.81 * (0.4 + 2 * x - y), -2000); });
}

TEST(PorePressureInitialisation, LinearInYFromATable) {
  // 5 kPa at the base to -3 kPa at 0.5 m, constant above
  expectPorePressures("{Method: pore pressure, Pore Pressure Table: [0.0, 5000, 0.5, -3000]}",
                      [](Real, Real y) { return y >= 0.5 ? -3000 : 5000 - 16000 * y; });
}

TEST(PorePressureInitialisation, DeckErrorsNameTheKey) {
  const auto expectError = [](const std::string& initialisation, const std::string& where,
                              const std::string& part) {
    try {
      (void)parse(columnDeck(initialisation));
      ADD_FAILURE() << "accepted: " << initialisation;
    } catch (const InputError& error) {
      EXPECT_EQ(error.where(), where) << error.what();
      EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
    }
  };
  expectError("{Method: pore pressure}", "Initialisation",
              "give exactly one of 'Phreatic Surface (m)' or 'Pore Pressure Table'");
  expectError(
      "{Method: pore pressure, Phreatic Surface (m): [0.0, 0.6], Pore Pressure Table: "
      "[0.0, 1.0]}",
      "Initialisation", "give exactly one of");
  expectError("{Method: pore pressure, Pore Pressure Table: [0.5, 1.0, 0.2, 2.0]}",
              "Initialisation/Pore Pressure Table",
              "y must increase from pair to pair; pair 2 has y = 0.2 after y = 0.5");
  expectError("{Method: pore pressure, Pore Pressure Table: [0.5, 1.0, 0.7]}",
              "Initialisation/Pore Pressure Table", "expected y, p_L pairs");
  expectError("{Method: uniform, Pore Pressure Table: [0.5, 1.0]}",
              "Initialisation/Pore Pressure Table", "Method");
}

}  // namespace
}  // namespace argine
