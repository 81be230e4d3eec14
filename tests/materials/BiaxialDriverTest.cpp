// Drained plane-strain biaxial test of one material point (constitutive driver): constant
// confining stress sigma_xx = sigma_3, axial compression d eps_yy < 0, eps_zz = 0.
//
// Analytical plateau (compression positive): sigma_1 = sigma_3 N_phi + 2 c sqrt(N_phi),
// N_phi = (1 + sin phi)/(1 - sin phi). With phi = 30 deg (N_phi = 3), c = 1e4/sqrt(3) Pa
// (2 c sqrt(3) = 2e4 Pa) and sigma_3 = 100 kPa: sigma_1 = 320 kPa, deviator 220 kPa.
// On the plateau the stress is stationary, so the strain increments are plastic:
// d eps = dlambda (m, 0, -1) in (xx, zz, yy) with m = N_psi, and
// d eps_vol / (d eps_xx - d eps_yy) = (m - 1)/(m + 1) = sin psi (= 1/3 here).
#include <gtest/gtest.h>

#include <cmath>

#include "argine/materials/SolidModel.hpp"

namespace argine {
namespace {

SolidSpec biaxialSoil(Real dilatancy) {
  SolidSpec spec;
  spec.model = SolidModel::MohrCoulomb;
  spec.youngs_modulus = 2.5e7;
  spec.poisson_ratio = 0.25;
  spec.cohesion = 1e4 / std::sqrt(3.0);
  spec.friction_angle = std::asin(0.5);
  spec.dilatancy_angle = dilatancy;
  spec.tension_cutoff = true;
  return spec;
}

struct DriverStep {
  Real stress[4];
  Real dstrain[4];
  int state;
};

/// One strain increment d eps_yy with sigma_xx held at `confining` (secant iteration on
/// d eps_xx; the response is piecewise linear, so it converges in a few iterations).
DriverStep driveStep(const SolidSpec& spec, const Real stress[4], Real& plastic, Real deps_yy,
                     Real confining) {
  auto attempt = [&](Real deps_xx, DriverStep& out, Real& eps_p) {
    for (int c = 0; c < 4; ++c) out.stress[c] = stress[c];
    out.dstrain[0] = deps_xx, out.dstrain[1] = deps_yy, out.dstrain[2] = 0, out.dstrain[3] = 0;
    eps_p = plastic;
    updateEffectiveStress(spec, 0.0, out.dstrain, out.stress, eps_p, out.state);
    return out.stress[0] - confining;
  };
  DriverStep a, b;
  Real pa, pb;
  Real xa = -deps_yy / 3, xb = xa * 1.1 + 1e-9;  // elastic guess: -lambda/(lambda + 2G)
  Real ga = attempt(xa, a, pa), gb = attempt(xb, b, pb);
  for (int it = 0; it < 50 && std::fabs(gb) > 1e-7; ++it) {
    const Real xn = xb - gb * (xb - xa) / (gb - ga);
    xa = xb, ga = gb;
    xb = xn;
    gb = attempt(xb, b, pb);
  }
  EXPECT_LT(std::fabs(gb), 1e-6);
  plastic = pb;
  return b;
}

void runBiaxial(Real dilatancy) {
  const SolidSpec spec = biaxialSoil(dilatancy);
  const Real confining = -1e5;
  Real stress[4] = {confining, confining, confining, 0};
  Real plastic = 0;
  Real peak = 0, deps_last[4] = {0, 0, 0, 0};
  int plastic_steps = 0;
  for (int n = 0; n < 2000; ++n) {  // axial strain 2 %
    const DriverStep s = driveStep(spec, stress, plastic, -1e-5, confining);
    for (int c = 0; c < 4; ++c) stress[c] = s.stress[c], deps_last[c] = s.dstrain[c];
    peak = std::max(peak, stress[0] - stress[1]);  // sigma_xx - sigma_yy (compression positive)
    if (s.state != kPlasticStateElastic) ++plastic_steps;
    // sigma_zz stays the intermediate principal stress.
    ASSERT_LE(stress[1], stress[2] + 1e-6);
    ASSERT_LE(stress[2], stress[0] + 1e-6);
  }
  const Real n_phi = 3.0, analytical = -confining * n_phi + 2e4 + confining;  // 220 kPa
  EXPECT_NEAR(peak, analytical, 1e-6 * analytical);
  EXPECT_NEAR(stress[0] - stress[1], analytical, 1e-6 * analytical);  // a plateau, no softening
  EXPECT_GT(plastic_steps, 1000);
  EXPECT_GT(plastic, 0);
  const Real ratio = (deps_last[0] + deps_last[1]) / (deps_last[0] - deps_last[1]);  // d eps_zz = 0
  EXPECT_NEAR(ratio, std::sin(dilatancy), 1e-6);
}

TEST(BiaxialDriver, PeakAndDilatancyNonAssociated) {
  runBiaxial(std::asin(1.0 / 3.0));
}

TEST(BiaxialDriver, PeakAndDilatancyZeroDilatancy) {
  runBiaxial(0.0);  // isochoric plastic flow: d eps_vol = 0 on the plateau
}

TEST(BiaxialDriver, PeakAndDilatancyAssociated) {
  runBiaxial(std::asin(0.5));
}

}  // namespace
}  // namespace argine
