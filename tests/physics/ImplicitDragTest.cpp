// [2Phase][Explicit] The implicit Darcy drag of the nodal solve (`Liquid Drag: implicit`,
// doc/theory.md Sec. 3.1, MomentumBalance.hpp): hand values, the undrained limit and the
// backward-Euler decay of the relative velocity that makes it stable for any Q dt.
#include <gtest/gtest.h>

#include <cmath>

#include "argine/physics/MomentumBalance.hpp"

namespace argine {
namespace {

// One node, one direction: F_L = 2 N, F_m = 10 N, Q = 100 kg/s, r = v_L - v_S = 0.5 m/s
// (v_L = 1 m/s), dt = 0.01 s, M~_L = 3 kg, M_L = 1.2 kg, M_S = 4 kg, no damping.
constexpr Real kLiquidForce = 2, kMixtureForce = 10, kDrag = 100, kRelative = 0.5;
constexpr Real kLiquidVelocity = 1, kStep = 0.01;
constexpr Real kIntrinsicMass = 3, kLiquidMass = 1.2, kSolidMass = 4;

TEST(ImplicitDrag, LiquidAccelerationMatchesHandValuesAndTheNewVelocities) {
  // Hand: numerator 2 - 100 * 0.5 + 100 * 0.01 * 10 / 4 = -45.5,
  // denominator 3 + 100 * 0.01 * (1 + 1.2 / 4) = 4.3, a_L = -10.581395...
  const Real a_l = implicitDragLiquidAcceleration(
      kLiquidForce, kMixtureForce, kDrag, kRelative, kLiquidVelocity, kStep, kIntrinsicMass,
      kLiquidMass, kSolidMass, true, 0.0, LocalDampingForm::StartOfStep);
  EXPECT_NEAR(a_l, -45.5 / 4.3, 1e-12);
  // It solves the liquid equation with the drag at t^{k+1} and a_S from the mixture one.
  const Real a_s = (kMixtureForce - kLiquidMass * a_l) / kSolidMass;
  EXPECT_NEAR(kIntrinsicMass * a_l, kLiquidForce - kDrag * (kRelative + kStep * (a_l - a_s)),
              1e-12);
  // Uncoupled (a_S = 0: fixed skeleton or a solid-fixed direction): (2 - 50) / (3 + 1) = -12.
  EXPECT_NEAR(implicitDragLiquidAcceleration(kLiquidForce, kMixtureForce, kDrag, kRelative,
                                             kLiquidVelocity, kStep, kIntrinsicMass, kLiquidMass,
                                             kSolidMass, false, 0.0, LocalDampingForm::StartOfStep),
              -12.0, 1e-12);
  // Local damping alpha = 0.2 acts on the numerator against v_L > 0: -45.5 - 0.2 * 45.5.
  EXPECT_NEAR(implicitDragLiquidAcceleration(kLiquidForce, kMixtureForce, kDrag, kRelative,
                                             kLiquidVelocity, kStep, kIntrinsicMass, kLiquidMass,
                                             kSolidMass, true, 0.2, LocalDampingForm::StartOfStep),
              -45.5 * 1.2 / 4.3, 1e-12);
  // The dissipative form (LocalDamping.hpp) with the denominator as the mass: v_L = 1 moves
  // steadily (mean velocity 1 - 0.5 * 0.01 * 45.5 / 4.3 > 0, cap 4.3 * 0.947 / 0.01 > 9.1):
  // the same -45.5 - 9.1.
  EXPECT_NEAR(implicitDragLiquidAcceleration(kLiquidForce, kMixtureForce, kDrag, kRelative,
                                             kLiquidVelocity, kStep, kIntrinsicMass, kLiquidMass,
                                             kSolidMass, true, 0.2, LocalDampingForm::Dissipative),
              -45.5 * 1.2 / 4.3, 1e-12);
  // v_L = 0.01: the mean velocity 0.01 - 0.0529 < 0, so the damping opposes it: -45.5 + 9.1
  // (the start-of-step form would give -45.5 - 9.1, against v_L^k).
  EXPECT_NEAR(implicitDragLiquidAcceleration(kLiquidForce, kMixtureForce, kDrag, kRelative, 0.01,
                                             kStep, kIntrinsicMass, kLiquidMass, kSolidMass, true,
                                             0.2, LocalDampingForm::Dissipative),
              -45.5 * 0.8 / 4.3, 1e-12);
}

TEST(ImplicitDrag, StrongDragMovesBothPhasesAsTheUndrainedMixture) {
  // Q dt -> infinity: a_L -> a_S -> F_m / (M_S + M_L) = 10 / 5.2, whatever F_L and r.
  const Real a_l = implicitDragLiquidAcceleration(
      kLiquidForce, kMixtureForce, 1e14, 0.0, kLiquidVelocity, kStep, kIntrinsicMass, kLiquidMass,
      kSolidMass, true, 0.0, LocalDampingForm::StartOfStep);
  const Real a_s = (kMixtureForce - kLiquidMass * a_l) / kSolidMass;
  EXPECT_NEAR(a_l, 10 / 5.2, 1e-9);
  EXPECT_NEAR(a_s, 10 / 5.2, 1e-9);
}

TEST(ImplicitDrag, RelativeVelocityDecaysForAnyDragTimesStep) {
  // No forces: r^{k+1} = r^k / (1 + dt Q (1 + M_L/M_S) / M~_L), backward Euler, for Q dt
  // from small to 1e6 times the liquid mass; the explicit drag, r (1 - dt Q (...) / M~_L),
  // changes sign and grows once dt Q (1 + M_L/M_S) / M~_L > 2.
  for (const Real q_dt_over_mass : {1e-3, 0.5, 2.5, 1e3, 1e6}) {
    const Real drag = q_dt_over_mass * kIntrinsicMass / kStep;
    const Real a_l = implicitDragLiquidAcceleration(0, 0, drag, kRelative, kLiquidVelocity, kStep,
                                                    kIntrinsicMass, kLiquidMass, kSolidMass, true,
                                                    0.0, LocalDampingForm::StartOfStep);
    const Real a_s = -kLiquidMass * a_l / kSolidMass;
    const Real next = kRelative + kStep * (a_l - a_s);
    const Real factor = 1 + q_dt_over_mass * (1 + kLiquidMass / kSolidMass);
    EXPECT_NEAR(next, kRelative / factor, 1e-12 * kRelative) << q_dt_over_mass;
    EXPECT_GT(next, 0) << q_dt_over_mass;
    EXPECT_LT(next, kRelative) << q_dt_over_mass;
  }
}

}  // namespace
}  // namespace argine
