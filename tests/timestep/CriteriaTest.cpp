// Critical time-step criteria (thesis Sec. 7, Table 4.4, Appendix 7.22-7.40) against hand
// computations, limits and monotonicity.
//
// Base point for the hand values (round numbers, g = 10 so that rho_L g / k is round):
//   L_i = 0.1 m, n = 0.4, rho_S = 2500, rho_L = 1000 kg/m^3, K_L = 2e9 Pa, E'_c = 1e7 Pa,
//   k = 1e-4 m/s, g = 10 m/s^2, f = 1, S_L = 1, dS_L/ds = 0.
// Derived: rho_dry = 0.6*2500 = 1500; rho_sat = 1500 + 400 = 1900; mu/kappa = rho_L g / k
//   = 1e4 / 1e-4 = 1e8 Pa s/m^2.
// Unsaturated state: S_L = 0.5, dS_L/ds = -1e-5 1/Pa:
//   K_e = 0.5 / (1e-5 + 0.5/2e9) = 0.5 / 1.000025e-5 = 49998.750031 Pa.
#include <gtest/gtest.h>

#include <cmath>
#include <set>
#include <string>

#include "argine/timestep/Criteria.hpp"

namespace argine {
namespace {

CriterionInput basePoint() {
  CriterionInput in;
  in.element_size = 0.1;
  in.porosity = 0.4;
  in.saturation = 1;
  in.saturation_suction_derivative = 0;
  in.solid_density = 2500;
  in.liquid_density = 1000;
  in.liquid_bulk_modulus = 2e9;
  in.constrained_modulus = 1e7;
  in.hydraulic_conductivity = 1e-4;
  in.gravity = 10;
  in.mass_scaling = 1;
  return in;
}

CriterionInput unsaturatedPoint() {
  CriterionInput in = basePoint();
  in.saturation = 0.5;
  in.saturation_suction_derivative = -1e-5;
  return in;
}

// Relative tolerance for hand values quoted to ~9 significant digits.
void expectRel(Real actual, Real expected, Real rel = 1e-8) {
  EXPECT_NEAR(actual, expected, rel * std::abs(expected));
}

// readsSaturationSlope tells TimeStepControl which criteria it may leave without the SWRC
// slope: exactly those whose step does not change when only dS_L/ds changes.
TEST(Criteria, ReadsSaturationSlopeExactlyWhereTheStepDependsOnIt) {
  const CriterionInput in = unsaturatedPoint();
  CriterionInput flat = in;
  flat.saturation_suction_derivative = 0;
  for (CriterionKind kind : kAllCriteria)
    EXPECT_EQ(criticalStep(kind, in) != criticalStep(kind, flat), readsSaturationSlope(kind))
        << criterionName(kind);
}

TEST(Criteria, NamesAreDistinctAndDispatchMatches) {
  std::set<std::string> names;
  const CriterionInput in = unsaturatedPoint();
  for (CriterionKind kind : kAllCriteria) {
    names.insert(criterionName(kind));
    EXPECT_GT(criticalStep(kind, in), 0.0) << criterionName(kind);
  }
  EXPECT_EQ(names.size(), 9u);
  EXPECT_EQ(criticalStep(CriterionKind::Mieremet, in), criticalStepMieremet(in));
  EXPECT_EQ(criticalStep(CriterionKind::UnsaturatedCoupled, in),
            criticalStepUnsaturatedCoupled(in));
}

TEST(Criteria, EffectiveLiquidStiffness) {
  expectRel(effectiveLiquidStiffness(basePoint()), 2e9, 1e-15);
  expectRel(effectiveLiquidStiffness(unsaturatedPoint()), 49998.750031, 1e-10);
  // The sign of dS/ds does not matter (thesis writes the storage as positive).
  CriterionInput positive = unsaturatedPoint();
  positive.saturation_suction_derivative = 1e-5;
  EXPECT_EQ(effectiveLiquidStiffness(positive), effectiveLiquidStiffness(unsaturatedPoint()));
}

TEST(Criteria, CflDryHand) {
  // dt = L / sqrt(E/rho_dry) = 0.1 * sqrt(1500/1e7) = 0.1 * 0.012247449 = 1.2247449e-3 s.
  expectRel(criticalStepCflDry(basePoint()), 1.224744871e-3);
}

TEST(Criteria, CflUndrainedHand) {
  // E_u = 1e7 + 2e9/0.4 = 5.01e9; dt = 0.1 * sqrt(1900 / 5.01e9) = 0.1 * 6.1582588e-4.
  expectRel(criticalStepCflUndrained(basePoint()), 6.158258820e-5);
  EXPECT_LT(criticalStepCflUndrained(basePoint()), criticalStepCflDry(basePoint()));
}

TEST(Criteria, ConsolidationHand) {
  // c_v = 1e-4 / (1000*10*(1/1e7 + 0.4/2e9)) = 1e-4 / (1e4 * 1.002e-7) = 0.0998004 m^2/s;
  // dt = 0.01 / (2 * 0.0998004) = 0.0501 s.
  expectRel(criticalStepConsolidation(basePoint()), 0.0501);
  // Consolidation ignores S_L (saturated reference).
  expectRel(criticalStepConsolidation(unsaturatedPoint()), 0.0501);
}

TEST(Criteria, InfiltrationHand) {
  // Eq. 4.63: 1/E + S n/K_L + n |dS/ds| = 1e-7 + 0.5*0.4/2e9 + 0.4e-5 = 4.1001e-6 1/Pa;
  // c = 1e-4 / (1e4 * 4.1001e-6) = 2.4389649e-3 m^2/s; dt = 0.01 / (2c) = 2.05005 s.
  expectRel(criticalStepInfiltration(unsaturatedPoint()), 2.05005);
  // Saturated with no storage it is the consolidation step (thesis note under Eq. 4.63).
  expectRel(criticalStepInfiltration(basePoint()), criticalStepConsolidation(basePoint()), 1e-14);
}

// Saturated column of Table 4.4 written out independently of the unsaturated code.
TEST(Criteria, LiquidAtSaturationEqualsSaturatedTable) {
  // omega_L = sqrt(2e9/1000)/0.1 = 14142.1356; xi_L = n mu/kappa / (2 omega rho_L)
  //   = 4e7 / (2 * 14142.1356 * 1000) = 1.41421356;
  // dt = 2/omega (-xi + sqrt(xi^2+1)) = 1.41421356e-4 * (sqrt(3) - sqrt(2)) = 4.49489743e-5.
  expectRel(criticalStepUnsaturatedLiquid(basePoint()), 4.494897428e-5);
}

TEST(Criteria, MixtureAtSaturationEqualsSaturatedTable) {
  // omega_M^2 = [1e7/(0.6*2500) + 0.6*2e9/(0.4*2500)] / 0.01 = (6666.667 + 1.2e6) * 100
  //   -> omega_M = 10984.838;
  // xi_M = n^2 mu/kappa / (2 (1-n) rho_S omega_M) = 0.16e8 / (2*1500*10984.838) = 0.48551770;
  // dt = (2/10984.838) (-0.4855177 + sqrt(1.2357275)) = 1.13996233e-4 s.
  expectRel(criticalStepUnsaturatedMixture(basePoint()), 1.139962330e-4);
}

TEST(Criteria, CoupledAtSaturationEqualsSaturatedTable) {
  // omega_C^2 = [2e9/1000 + 1e7/(2500*0.6) + 0.6*2e9/(0.4*2500)] / 0.01
  //   = (2e6 + 6666.667 + 1.2e6) * 100 -> omega_C = 17907.168;
  // xi_C = 0.4e8/(2*17907.168) * (0.4/(0.6*2500) + 1/1000) = 1116.8736 * 1.2666667e-3
  //   = 1.41470350; dt = (2/17907.168)(-1.4147035 + sqrt(3.0013814)) = 3.54882874e-5 s.
  expectRel(criticalStepUnsaturatedCoupled(basePoint()), 3.548828738e-5);
}

TEST(Criteria, UnsaturatedYerroHand) {
  const CriterionInput in = unsaturatedPoint();
  // q_L = S n mu/kappa = 0.5*0.4*1e8 = 2e7.
  // Liquid: omega = sqrt(49998.75/1000)/0.1 = 70.709794; xi = 2e7/(2*70.709794*1000)
  //   = 141.423124; dt = 2/(omega (xi + sqrt(xi^2+1))) = 9.99987501e-5 s.
  expectRel(criticalStepUnsaturatedLiquid(in), 9.999875006e-5);
  // Mixture: omega^2 = [1e7/0.6 + (2.5 - 0.5)*49998.75] / 2500 / 0.01 -> omega = 818.942346;
  //   xi = S^2 n^2 mu/kappa / (2 (1-n) rho_S omega) = 0.04e8/(2*1500*818.942346) = 1.62811624;
  //   dt = (2/818.942346)(-1.62811624 + sqrt(3.65076247)) = 6.90111145e-4 s.
  expectRel(criticalStepUnsaturatedMixture(in), 6.901111449e-4);
  // Coupled: omega^2 = {49998.75 [1/1000 + (2.5-0.5)/2500] + 1e7/(2500*0.6)} / 0.01
  //   = (49998.75*1.8e-3 + 6666.667)*100 -> omega = 821.989320;
  //   xi = 2e7/(2*821.98932) * (0.5*0.4/1500 + 1e-3) = 12165.6082 * 1.1333333e-3 = 13.7876893;
  //   dt = 2/(omega (xi + sqrt(xi^2+1))) = 8.81195606e-5 s.
  expectRel(criticalStepUnsaturatedCoupled(in), 8.811956055e-5);
}

TEST(Criteria, MieremetSaturatedHandAsAnura3D) {
  // a = n rho_sat g / ((1-n) rho_S k) = 0.4*1900*10/(0.6*2500*1e-4) = 50666.667 1/s
  // b = 4 [n rho_sat K + (1-2n) rho_L K + n rho_L E] / (n (1-n) rho_S rho_L L^2)
  //   = 4 [1.52e12 + 4e11 + 4e9] / (0.24*2500*1000*0.01) = 1.28266667e9
  // d = 16 E K / ((1-n) rho_S rho_L L^4) = 3.2e17 / (1500*1000*1e-4) = 2.13333333e15
  // B = b + sqrt(b^2 - 4d) = 2.56200261e9
  // dt = (-2a + sqrt(4a^2 + 8B)) / B = 2.89089036e-5 s.
  expectRel(criticalStepMieremet(basePoint()), 2.890890358e-5);
}

TEST(Criteria, MieremetUnsaturatedAdaptationHand) {
  // Sec. 7.2: K_L -> K_e = 49998.75, rho_sat -> rho_m = 1500 + 0.5*0.4*1000 = 1700,
  // a gets S_L^2: a = 0.25*0.4*1700*10/(1500*1e-4) = 11333.333;
  // b = 4 [0.4*1700*K_e + 0.2*1000*K_e + 0.4*1000*1e7]/6000 = 2695999.27;
  // d = 16*1e7*K_e/150 = 5.33320000e10; B = b + sqrt(b^2 - 4d) = 5352140.08;
  // dt = (-2a + sqrt(4a^2 + 8B))/B = 1.72939581e-4 s.
  expectRel(criticalStepMieremet(unsaturatedPoint()), 1.729395809e-4);
}

TEST(Criteria, MieremetLiquidDragHand) {
  // Same b, d, B as the adaptation above (K_e = 49998.75, rho_m = 1700): b = 2695999.27,
  // d = 5.33320000e10, B = 5352140.08; the damping term carries S_L once:
  // a = S_L n rho_m g / ((1-n) rho_S k) = 0.5*0.4*1700*10/(1500*1e-4) = 22666.667 1/s;
  // dt = (-2a + sqrt(4a^2 + 8B))/B = (-45333.333 + sqrt(2.05511e9 + 4.28171e7))/5352140.08
  //    = 8.77804367e-5 s (half of the S_L^2 form's 1.729e-4 here: drag-dominated).
  expectRel(criticalStepMieremetLiquidDrag(unsaturatedPoint()), 8.778043668e-5);
  EXPECT_LT(criticalStepMieremetLiquidDrag(unsaturatedPoint()),
            criticalStepMieremet(unsaturatedPoint()));
  // Saturated: the two forms are the same (Table 4.5, S_L = 1).
  EXPECT_EQ(criticalStepMieremetLiquidDrag(basePoint()), criticalStepMieremet(basePoint()));
  // Strong drag: dt -> 2/a, a = 0.5*0.4*1700*10/(1500*1e-12) = 2.2666667e12 -> 8.8235294e-13 s.
  CriterionInput tight = unsaturatedPoint();
  tight.hydraulic_conductivity = 1e-12;
  expectRel(criticalStepMieremetLiquidDrag(tight), 8.8235294118e-13, 1e-6);
  // No liquid: no drag term, the same as the S_L^2 form.
  CriterionInput dry = unsaturatedPoint();
  dry.saturation = 0;
  EXPECT_EQ(criticalStepMieremetLiquidDrag(dry), criticalStepMieremet(dry));
  EXPECT_EQ(criticalStep(CriterionKind::MieremetLiquidDrag, unsaturatedPoint()),
            criticalStepMieremetLiquidDrag(unsaturatedPoint()));
}

TEST(Criteria, MieremetMassScaling) {
  // f = 4: a/4, b/4, d/16 in the saturated hand computation above -> 7.89997943e-5 s.
  CriterionInput in = basePoint();
  in.mass_scaling = 4;
  expectRel(criticalStepMieremet(in), 7.899979434e-5);
}

TEST(Criteria, WaveCriteriaScaleWithSqrtOfMassScalingParabolicOnesDoNot) {
  CriterionInput scaled = basePoint();
  scaled.mass_scaling = 9;
  expectRel(criticalStepCflDry(scaled), 3 * criticalStepCflDry(basePoint()), 1e-14);
  expectRel(criticalStepCflUndrained(scaled), 3 * criticalStepCflUndrained(basePoint()), 1e-14);
  EXPECT_EQ(criticalStepConsolidation(scaled), criticalStepConsolidation(basePoint()));
  EXPECT_EQ(criticalStepInfiltration(scaled), criticalStepInfiltration(basePoint()));
  // Yerro forms: omega ~ f^-1/2 and xi ~ f^-1/2, so dt grows between sqrt(f) (no drag,
  // dt = 2/omega) and f (drag-dominated, dt ~ 1/(omega xi) ~ rho/q); Mieremet likewise
  // (dt = 2/sqrt(lambda_max) without drag, 2/a with strong drag).
  for (CriterionKind kind : {CriterionKind::UnsaturatedLiquid, CriterionKind::UnsaturatedMixture,
                             CriterionKind::UnsaturatedCoupled, CriterionKind::Mieremet,
                             CriterionKind::MieremetLiquidDrag}) {
    const Real ratio = criticalStep(kind, scaled) / criticalStep(kind, basePoint());
    EXPECT_GT(ratio, 3.0 - 1e-12) << criterionName(kind);
    EXPECT_LT(ratio, 9.0 + 1e-12) << criterionName(kind);
  }
}

TEST(Criteria, HighPermeabilityLimits) {
  CriterionInput in = basePoint();
  in.hydraulic_conductivity = 1e12;  // drag -> 0
  // Yerro forms: xi -> 0, dt -> 2/omega. Liquid: 2/14142.1356 = 1.41421356e-4.
  expectRel(criticalStepUnsaturatedLiquid(in), 1.414213562e-4, 1e-6);
  // Mieremet: a -> 0, dt -> 2 / sqrt(lambda_max), lambda_max the largest eigenvalue of the
  // undamped two-phase element (Biot's fast wave): with u'' -> -(4/L^2) u,
  //   M = diag(n rho_L, (1-n) rho_S), S = (4/L^2) [[n K, (1-n) K], [(1-n) K, (1-n)^2 K/n + E]].
  const Real n = 0.4, K = 2e9, E = 1e7, rho_l = 1000, rho_s = 2500, w = 4 / 0.01;
  const Real a11 = w * n * K / (n * rho_l), a12 = w * (1 - n) * K / (n * rho_l);
  const Real a21 = w * (1 - n) * K / ((1 - n) * rho_s);
  const Real a22 = w * ((1 - n) * (1 - n) * K / n + E) / ((1 - n) * rho_s);
  const Real tr = a11 + a22, det = a11 * a22 - a12 * a21;
  const Real lambda_max = 0.5 * (tr + std::sqrt(tr * tr - 4 * det));
  expectRel(criticalStepMieremet(in), 2 / std::sqrt(lambda_max), 1e-6);
  // That is shorter than the undrained CFL step (the fast wave outruns the undrained one).
  EXPECT_LT(criticalStepMieremet(in), criticalStepCflUndrained(in));
}

TEST(Criteria, LowPermeabilityLimits) {
  CriterionInput in = basePoint();
  in.hydraulic_conductivity = 1e-12;  // drag dominates
  // Mieremet: dt -> 2/a, a = 0.4*1900*10/(0.6*2500*1e-12) = 7600/1.5e-9 = 5.0666667e12
  // -> 3.9473684e-13 s.
  expectRel(criticalStepMieremet(in), 3.9473684211e-13, 1e-6);
  // Liquid: dt -> 2 rho_L / q_L = 2*1000/(0.4*1e4/1e-12) = 5e-13 s.
  expectRel(criticalStepUnsaturatedLiquid(in), 5e-13, 1e-6);
  // k = 0: the explicit drag admits no finite step; dry criteria are unaffected.
  in.hydraulic_conductivity = 0;
  EXPECT_EQ(criticalStepMieremet(in), 0.0);
  EXPECT_EQ(criticalStepUnsaturatedLiquid(in), 0.0);
  EXPECT_TRUE(std::isinf(criticalStepConsolidation(in)));
  EXPECT_GT(criticalStepCflDry(in), 0.0);
}

TEST(Criteria, UnsaturatedStepsExceedSaturatedOnes) {
  // Thesis Sec. 7.3: the critical step grows when the soil desaturates.
  for (CriterionKind kind :
       {CriterionKind::UnsaturatedLiquid, CriterionKind::UnsaturatedMixture,
        CriterionKind::UnsaturatedCoupled, CriterionKind::Mieremet, CriterionKind::Infiltration}) {
    EXPECT_GT(criticalStep(kind, unsaturatedPoint()), criticalStep(kind, basePoint()))
        << criterionName(kind);
  }
}

TEST(Criteria, DryPointWithoutLiquid) {
  CriterionInput in = unsaturatedPoint();
  in.saturation = 0;
  EXPECT_EQ(effectiveLiquidStiffness(in), 0.0);
  EXPECT_TRUE(std::isinf(criticalStepUnsaturatedLiquid(in)));
  // Mixture with K_e = 0 and no drag: dt = 2/omega, omega = sqrt(1e7/(0.6*2500))/0.1
  //   = 816.49658 -> 2.44948974e-3 s.
  expectRel(criticalStepUnsaturatedMixture(in), 2.449489743e-3);
  EXPECT_GT(criticalStepMieremet(in), 0.0);
}

TEST(Criteria, MonotonicInElementSize) {
  for (const CriterionInput& point : {basePoint(), unsaturatedPoint()}) {
    for (CriterionKind kind : kAllCriteria) {
      Real previous = 0;
      for (Real dx : {0.01, 0.035, 0.1, 0.35, 1.0}) {
        CriterionInput in = point;
        in.element_size = dx;
        const Real dt = criticalStep(kind, in);
        EXPECT_GT(dt, previous) << criterionName(kind) << " dx = " << dx;
        previous = dt;
      }
    }
  }
}

TEST(Criteria, UsableInsideKernel) {
  const CriterionInput in = basePoint();
  Real smallest = 0;
  Kokkos::parallel_reduce(
      "dt", Kokkos::RangePolicy<ExecSpace>(0, 8),
      KOKKOS_LAMBDA(const int i, Real& m) {
        const Real dt = criticalStep(static_cast<CriterionKind>(i), in);
        if (dt < m) m = dt;
      },
      Kokkos::Min<Real>(smallest));
  // The smallest at the base point is Mieremet's 2.89089036e-5 s.
  expectRel(smallest, 2.890890358e-5);
}

}  // namespace
}  // namespace argine
