// Local damping forms (physics/LocalDamping.hpp; doc/stability.md "A dissipative local
// damping"): hand values of the damped force, the one-degree-of-freedom oscillator and the
// two-equation element of Eq. 4.67 stepped just above the start-of-step form's damped limit
// (which grows there; the dissipative form's discrete energy never increases), and damped
// columns under gravity that come to rest with either form.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "Harness.hpp"
#include "argine/physics/LocalDamping.hpp"
#include "argine/timestep/Criteria.hpp"

namespace argine {
namespace {

using test::hostCopy;
using test::makeStage;
using test::runUntil;

constexpr LocalDampingForm kStart = LocalDampingForm::StartOfStep;
constexpr LocalDampingForm kDissipative = LocalDampingForm::Dissipative;

TEST(LocalDamping, StartOfStepFormIsTheForceMinusAlphaItsMagnitudeAgainstTheVelocity) {
  // -alpha |F| sign(v^k), whatever the mass and the step.
  EXPECT_EQ(dampedForce(kStart, 0.2, -10.0, 3.0, 2.0, 0.1), -12.0);
  EXPECT_EQ(dampedForce(kStart, 0.2, -10.0, -3.0, 2.0, 0.1), -8.0);
  EXPECT_EQ(dampedForce(kStart, 0.2, 10.0, 0.0, 2.0, 0.1), 10.0);  // at rest: nothing to oppose
  // The same bits as the force plus localDampingForce (the form before the choice existed).
  for (const Real v : {-1.3, 0.0, 0.7})
    for (const Real f : {-3.1, 0.0, 2.9})
      EXPECT_EQ(dampedForce(kStart, 0.75, f, v, 1.7, 0.01), f + localDampingForce(0.75, f, v));
}

TEST(LocalDampingDissipative, HandValues) {
  // A node moving steadily: v = 3, F = -10, m = 2, dt = 0.1: mean velocity 3 - 0.5 * 0.1 *
  // 10 / 2 = 2.75 > 0 and cap m |vbar| / dt = 55 > alpha |F| = 2: the start-of-step value.
  EXPECT_DOUBLE_EQ(dampedForce(kDissipative, 0.2, -10.0, 3.0, 2.0, 0.1), -12.0);
  // The sign-alternating mode: v = 2, F = -100, m = 1, dt = 0.1: v* = -8, mean -3 < 0, cap
  // 1 * 3 / 0.1 = 30. alpha 0.1: |D| = 10 against the mean velocity, -100 + 10 = -90 (the
  // start-of-step form: -110, adding to the force).
  EXPECT_DOUBLE_EQ(dampedForce(kDissipative, 0.1, -100.0, 2.0, 1.0, 0.1), -90.0);
  EXPECT_DOUBLE_EQ(dampedForce(kStart, 0.1, -100.0, 2.0, 1.0, 0.1), -110.0);
  // alpha 0.75: alpha |F| = 75 > cap 30, so |D| = 30: -70, v^{k+1} = 2 - 7 = -5 = dt F / (2m)
  // (the mean velocity brought to zero, no further); start-of-step: -175, v^{k+1} = -15.5.
  EXPECT_DOUBLE_EQ(dampedForce(kDissipative, 0.75, -100.0, 2.0, 1.0, 0.1), -70.0);
  EXPECT_DOUBLE_EQ(dampedForce(kStart, 0.75, -100.0, 2.0, 1.0, 0.1), -175.0);
  // From rest: v = 0, F = 10, m = 1, dt = 0.1: mean 0.5, cap 5 < alpha |F| = 7.5: 10 - 5 = 5;
  // alpha 0.2: 10 - 2 = 8 (start-of-step: 10, no damping at rest).
  EXPECT_DOUBLE_EQ(dampedForce(kDissipative, 0.75, 10.0, 0.0, 1.0, 0.1), 5.0);
  EXPECT_DOUBLE_EQ(dampedForce(kDissipative, 0.2, 10.0, 0.0, 1.0, 0.1), 8.0);
  // Mean velocity exactly zero (v = -dt F / (2m) = -0.5): nothing to oppose.
  EXPECT_EQ(dampedForce(kDissipative, 0.75, 10.0, -0.5, 1.0, 0.1), 10.0);
  // No force, or no damping: the force itself.
  EXPECT_EQ(dampedForce(kDissipative, 0.75, 0.0, 2.0, 1.0, 0.1), 0.0);
  EXPECT_EQ(dampedForce(kDissipative, 0.0, -3.7, 2.0, 1.3, 0.1), -3.7);
  // dt = 0 (no step): the start-of-step value, no division by zero.
  EXPECT_EQ(dampedForce(kDissipative, 0.2, -10.0, 3.0, 2.0, 0.0), -12.0);
  EXPECT_EQ(dampedForce(kDissipative, 0.75, 10.0, 0.0, 1.0, 0.0), 10.0);
}

/// The discrete energy the undamped explicit step keeps exactly (u at t^k, v at t^{k+1},
/// F = -k u the force of that step): m (v - dt F / (2m))^2 + (k - dt^2 k^2 / (4m)) u^2,
/// positive definite for dt < 2 sqrt(m/k) (LocalDamping.hpp), times 1/2.
Real oscillatorEnergy(Real u, Real v, Real k, Real m, Real dt) {
  const Real shifted = v + dt * k * u / (2 * m);
  return 0.5 * (m * shifted * shifted + (k - dt * dt * k * k / (4 * m)) * u * u);
}

struct OscillatorRun {
  Real largest = 0;          ///< largest |u| reached
  Real final_amplitude = 0;  ///< |u| + |v| dt at the end
  Real energy_rise = 0;      ///< largest one-step rise of oscillatorEnergy / the initial one
};

/// m u'' = -k u stepped as the solver steps a node: a = dampedForce / m, v += dt a,
/// u += dt v; from u = 1 at rest.
OscillatorRun runOscillator(LocalDampingForm form, Real alpha, Real dt, int steps) {
  const Real k = 1, m = 1;
  Real u = 1, v = 0;
  OscillatorRun run;
  Real energy = -1, initial = 0;
  for (int step = 0; step < steps && std::abs(u) < 1e6; ++step) {
    const Real force = -k * u;
    v += dt * dampedForce(form, alpha, force, v, m, dt) / m;
    const Real next = oscillatorEnergy(u, v, k, m, dt);
    if (energy < 0) initial = next;
    if (energy >= 0) run.energy_rise = std::max(run.energy_rise, (next - energy) / initial);
    energy = next;
    u += dt * v;
    run.largest = std::max(run.largest, std::abs(u));
  }
  run.final_amplitude = std::abs(u) + std::abs(v) * dt;
  return run;
}

TEST(LocalDampingDissipative, OscillatorAboveTheStartOfStepLimitLosesEnergyEveryStep) {
  // omega = 1: the undamped limit is dt = 2; the start-of-step form at alpha = 0.75 acts as
  // masses / 1.75 in the alternating mode, limit 2 / sqrt(1.75) = 1.512.
  const Real alpha = 0.75;
  for (const Real dt : {1.6, 1.8, 1.95}) {
    const OscillatorRun start = runOscillator(kStart, alpha, dt, 2000);
    EXPECT_GT(start.largest, 1e6) << "dt = " << dt;  // grows
    const OscillatorRun dissipative = runOscillator(kDissipative, alpha, dt, 2000);
    EXPECT_LE(dissipative.energy_rise, 1e-14) << "dt = " << dt;  // never increases
    EXPECT_LE(dissipative.largest, 1.0) << "dt = " << dt;
    EXPECT_LT(dissipative.final_amplitude, 1e-3) << "dt = " << dt;  // and comes to rest
  }
  // Below 1.512 both are stable and come to rest.
  for (const LocalDampingForm form : {kStart, kDissipative}) {
    const OscillatorRun run = runOscillator(form, alpha, 0.2, 2000);
    EXPECT_LE(run.largest, 1.0);
    EXPECT_LT(run.final_amplitude, 1e-3);
  }
}

/// The levee of verification/stability/hydraulic_head (SI): n 0.4, rho_S 2700, K_L 8e7 Pa,
/// E 50 MPa, nu 0.3, kappa 4e-11 m^2, saturated, 0.42 m cells, mass scaling 60.
CriterionInput leveePoint() {
  CriterionInput in;
  in.element_size = 0.42;
  in.porosity = 0.4;
  in.saturation = 1;
  in.solid_density = 2700;
  in.liquid_density = 1000;
  in.liquid_bulk_modulus = 8e7;
  in.constrained_modulus = 5e7 * 0.7 / (1.3 * 0.4);
  in.hydraulic_conductivity = 4e-11 * 1000 * kStandardGravity / 1e-3;
  in.gravity = kStandardGravity;
  in.mass_scaling = 60;
  return in;
}

/// The largest amplitude (over the initial one) of the explicit two-equation element at the
/// Nyquist wave number k^2 = 4/L^2 (Eq. 4.67's system: liquid and mixture momentum, Darcy
/// drag q, p_L = -(K_L/n) [(1-n) div u_S + n div u_L]), stepped as the solver steps a node:
/// the liquid equation (solveLiquidMomentum), then the mixture with the liquid inertia
/// M_L a_L (solveMixtureMomentum), each damped by dampedForce, then v += dt a, u += dt v.
Real twoEquationGrowth(const CriterionInput& in, LocalDampingForm form, Real alpha, Real dt,
                       int steps) {
  const Real n = in.porosity, k2 = 4 / (in.element_size * in.element_size);
  const Real K = in.liquid_bulk_modulus, E = in.constrained_modulus, f = in.mass_scaling;
  const Real q = liquidDrag(in);
  const Real m_solid = (1 - n) * in.solid_density * f, m_liquid = in.liquid_density * f;
  const Real m_liquid_in_mixture = n * in.saturation * in.liquid_density * f;
  Real us = 1e-6, ul = -2e-6, vs = 0, vl = 0, largest = 0;
  for (int step = 0; step < steps; ++step) {
    const Real pressure_term = (K / n) * k2 * ((1 - n) * us + n * ul);
    const Real force_liquid = -pressure_term - q * (vl - vs);
    const Real al = dampedForce(form, alpha, force_liquid, vl, m_liquid, dt) / m_liquid;
    const Real force_mixture = -E * k2 * us - pressure_term - m_liquid_in_mixture * al;
    const Real as = dampedForce(form, alpha, force_mixture, vs, m_solid, dt) / m_solid;
    vl += dt * al;
    vs += dt * as;
    ul += dt * vl;
    us += dt * vs;
    largest = std::max({largest, std::abs(us), std::abs(ul)});
    if (!(largest < 1)) break;
  }
  return largest / 2e-6;
}

TEST(LocalDampingDissipative, TwoEquationElementRunsAtTheUndampedCriterion) {
  const CriterionInput in = leveePoint();
  const Real criterion = criticalStepMieremetLiquidDrag(in);  // blind to the damping
  // Undamped, the element runs at the criterion.
  EXPECT_LT(twoEquationGrowth(in, kStart, 0, criterion, 4000), 1.5);
  for (const Real factor : {0.95, 1.0}) {
    std::printf(
        "[ two-equation element ] %.2f x %.4g s: growth start-of-step %.3g, dissipative "
        "%.3g\n",
        factor, criterion, twoEquationGrowth(in, kStart, 0.75, factor * criterion, 4000),
        twoEquationGrowth(in, kDissipative, 0.75, factor * criterion, 4000));
    // Start-of-step damping 0.75 blows it up (the damped limit is ~0.5 x the undamped one)...
    EXPECT_GT(twoEquationGrowth(in, kStart, 0.75, factor * criterion, 4000), 1e3) << factor;
    // ...the dissipative form does not.
    EXPECT_LT(twoEquationGrowth(in, kDissipative, 0.75, factor * criterion, 4000), 1.5) << factor;
  }
}

/// The column of ExplicitTwoPhase.DryColumnUnderGravityReachesGeostaticStress (H = 1 m, 10
/// elements, fixed base, rollers, local damping 0.3, 3 s) with the given damping form; or
/// saturated with impermeable base and sides (the locked directions of
/// constrainAccelerations) and a drained top. Returns the final kinetic energy over m g H.
Real dampedColumnAtRest(LocalDampingForm form, bool saturated, Real* stress_error) {
  const MaterialSpec soil =
      saturated ? test::elasticMaterial("clay", PhaseModel::Saturated, 1e7, 0.3, 0.4, 1e-3, 2e7)
                : test::elasticMaterial("sand", PhaseModel::Dry, 1e6, 0.3, 0.4);
  test::Column column(10, 0.1, 1.0, soil);
  ExplicitTwoPhaseSolver solver(column.mesh, column.points, column.materials);
  StageSpec stage = makeStage(
      "gravity", SolverKind::QuasiStatic, 9.81, 0.3, test::columnBoundaries(),
      saturated ? std::vector<CriterionKind>{CriterionKind::CflUndrained, CriterionKind::Mieremet}
                : std::vector<CriterionKind>{CriterionKind::CflDry});
  stage.local_damping_form = form;
  solver.beginStage(stage);
  runUntil(solver, 3.0);
  // Effective vertical stress against -(rho_sat or rho_dry - buoyancy) g (H - y) at the
  // element mid-heights.
  const Real unit_weight = saturated ? (0.6 * 2650 + 0.4 * 1000 - 1000) * 9.81 : 1590 * 9.81;
  const auto y0 = hostCopy(column.points.initial_position);
  const auto stress = hostCopy(column.points.stress_effective);
  Real worst = 0;
  for (int p = 0; p < column.points.count; ++p) {
    const Real y_mid = (std::floor(y0(p, 1) / 0.1) + 0.5) * 0.1;
    worst = std::max(worst, std::abs(stress(p, YY) + unit_weight * (1.0 - y_mid)));
  }
  *stress_error = worst / unit_weight;
  const Real mass = saturated ? 0.6 * 2650 + 0.4 * 1000 : 1590;
  const StepDiagnostics& d = solver.diagnostics();
  return (d.kinetic_energy_solid + d.kinetic_energy_liquid) / (mass * 9.81 * 1.0 * 0.1);
}

TEST(LocalDampingDissipative, DampedColumnsUnderGravityComeToRestInBothForms) {
  for (const bool saturated : {false, true}) {
    for (const LocalDampingForm form : {kStart, kDissipative}) {
      Real stress_error = 0;
      const Real kinetic = dampedColumnAtRest(form, saturated, &stress_error);
      std::printf("[ damped column ] %s, %s: kinetic / (m g H) %.3g, stress error %.3g rho g H\n",
                  saturated ? "saturated" : "dry", form == kStart ? "start-of-step" : "dissipative",
                  kinetic, stress_error);
      EXPECT_LT(kinetic, 1e-8) << saturated << " " << static_cast<int>(form);
      EXPECT_LT(stress_error, 0.02) << saturated << " " << static_cast<int>(form);
    }
  }
}

}  // namespace
}  // namespace argine
