// [2Phase][Transfer][APIC] The affine particle-in-cell transfer (Jiang et al. 2015): the
// round trip grid -> points -> grid keeps linear and angular momentum of both phases to
// round-off, and leaves no point velocity the grid cannot see.
#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "TestScenes.hpp"
#include "argine/transfer/ActiveNodes.hpp"
#include "argine/transfer/GridFields.hpp"
#include "argine/transfer/NodeRecords.hpp"
#include "argine/transfer/PointShapes.hpp"
#include "argine/transfer/TwoPhaseTransfer.hpp"

namespace argine {
namespace {

using test::hostCopy;
using test::liquidFlags;

/// A scene of nx x ny cells of `type` with points in every element (every third dry),
/// random masses and positions jittered inside their elements' interiors (the shapes are
/// evaluated where the points are), and random nodal velocities of both phases.
struct Scene {
  Mesh mesh;
  MaterialPoints points;
  PointShapes shapes;
  GridFields grid;
  ActiveNodes active;
};

Scene makeScene(Mesh mesh, unsigned seed) {
  Scene s;
  const ElementType type = mesh.type;
  s.mesh = std::move(mesh);
  s.points = test::seedUniform(s.mesh);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  auto material = hostCopy(s.points.material);
  auto ms = hostCopy(s.points.mass_solid), ml = hostCopy(s.points.mass_liquid);
  auto rho = hostCopy(s.points.density_liquid);
  const auto element = hostCopy(s.points.element);
  auto local = hostCopy(s.points.local), position = hostCopy(s.points.position);
  const auto X = hostCopy(s.mesh.coordinates);
  const auto C = hostCopy(s.mesh.connectivity);
  for (int p = 0; p < s.points.count; ++p) {
    material(p) = p % 3 == 2 ? 1 : 0;
    ms(p) = 2 + u(rng);
    ml(p) = material(p) == 0 ? 1 + 0.5 * u(rng) : 0;
    rho(p) = material(p) == 0 ? 1000 + 10 * u(rng) : 0;
    // jitter inside the element: Quad4 xi in [-0.9, 0.9]^2, Tri3 barycentric interior
    Real xi[kDim] = {local(p, 0) + 0.3 * u(rng), local(p, 1) + 0.3 * u(rng)};
    if (type == ElementType::Tri3) {
      xi[0] = 0.1 + 0.35 * (1 + u(rng)) * 0.5;
      xi[1] = 0.1 + 0.35 * (1 + u(rng)) * 0.5;
    }
    const int e = element(p);
    Real Xe[4][kDim];
    for (int a = 0; a < s.mesh.nodesPerElement(); ++a)
      for (int d = 0; d < kDim; ++d) Xe[a][d] = X(C(e, a), d);
    Real x[kDim];
    if (type == ElementType::Quad4)
      mapToPhysical<Quad4>(Xe, xi, x);
    else
      mapToPhysical<Tri3>(Xe, xi, x);
    for (int d = 0; d < kDim; ++d) {
      local(p, d) = xi[d];
      position(p, d) = x[d];
    }
  }
  Kokkos::deep_copy(s.points.material, material);
  Kokkos::deep_copy(s.points.mass_solid, ms);
  Kokkos::deep_copy(s.points.mass_liquid, ml);
  Kokkos::deep_copy(s.points.density_liquid, rho);
  Kokkos::deep_copy(s.points.local, local);
  Kokkos::deep_copy(s.points.position, position);
  evaluatePointShapes(s.mesh, s.points, s.shapes);
  s.grid.allocate(s.mesh.numNodes());
  s.active = ActiveNodes(s.mesh.numNodes());
  s.active.rebuild(s.mesh, s.points);
  return s;
}

Scene makeScene(ElementType type, unsigned seed) {
  return makeScene(test::rectangleMesh(3, 2, 1.5, 1.0, type, 10.0, -3.0), seed);  // off the origin
}

/// Random nodal velocities of both phases (the grid's v~ = v + dt a with a = 0).
void randomGridVelocities(GridFields& grid, int nodes, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  for (auto field : {grid.velocity_solid_i, grid.velocity_liquid_i}) {
    auto host = Kokkos::create_mirror_view(field);
    for (int i = 0; i < nodes; ++i)
      for (int d = 0; d < kDim; ++d) host(i, d) = u(rng);
    Kokkos::deep_copy(field, host);
  }
}

/// Linear (x, y) and angular (z) momentum of nodal momenta `momentum` at the mesh nodes.
struct Momenta {
  Real linear[kDim] = {0, 0};
  Real angular = 0;
};

template <class Momentum, class Coordinates>
Momenta momentaOf(const Momentum& momentum, const Coordinates& X) {
  Momenta m;
  for (int i = 0; i < static_cast<int>(X.extent(0)); ++i) {
    m.linear[0] += momentum(i, 0);
    m.linear[1] += momentum(i, 1);
    m.angular += X(i, 0) * momentum(i, 1) - X(i, 1) * momentum(i, 0);
  }
  return m;
}

/// The grid momenta before (m_i v~_i, from the masses of a P2G) and after the round trip
/// G2P (velocity update with dt a = 0) -> P2G (the remap), per phase, for `transfer`.
struct RoundTrip {
  Momenta solid_before, solid_after, liquid_before, liquid_after;
  Real solid_scale = 0, liquid_scale = 0;  ///< sum over nodes of |m v| (|x| + 1)
};

RoundTrip roundTrip(Scene& s, const TransferSettings& transfer) {
  NodeRecords records;
  mapPointsToGrid(s.points, s.shapes, liquidFlags(), 0.0, transfer, s.active, records, s.grid);
  randomGridVelocities(s.grid, s.mesh.numNodes(), 7);
  Kokkos::deep_copy(s.grid.acceleration_solid_i, 0.0);
  Kokkos::deep_copy(s.grid.acceleration_liquid_i, 0.0);
  const auto X = hostCopy(s.mesh.coordinates);
  const auto ms = hostCopy(s.grid.mass_solid_i), ml = hostCopy(s.grid.mass_liquid_intrinsic_i);
  const auto vs = hostCopy(s.grid.velocity_solid_i), vl = hostCopy(s.grid.velocity_liquid_i);
  Kokkos::View<Real*[kDim], Kokkos::HostSpace> ps("ps", X.extent(0)), pl("pl", X.extent(0));
  for (int i = 0; i < static_cast<int>(X.extent(0)); ++i)
    for (int d = 0; d < kDim; ++d) {
      ps(i, d) = ms(i) * vs(i, d);
      pl(i, d) = ml(i) * vl(i, d);
    }
  RoundTrip r;
  for (int i = 0; i < static_cast<int>(X.extent(0)); ++i) {
    const Real arm = std::hypot(X(i, 0), X(i, 1)) + 1;
    r.solid_scale += std::hypot(ps(i, 0), ps(i, 1)) * arm;
    r.liquid_scale += std::hypot(pl(i, 0), pl(i, 1)) * arm;
  }
  r.solid_before = momentaOf(ps, X);
  r.liquid_before = momentaOf(pl, X);
  updatePointVelocitiesAndMapMomenta(s.shapes, liquidFlags(), s.active, 0.01, transfer, s.points,
                                     records, s.grid);
  r.solid_after = momentaOf(hostCopy(s.grid.momentum_solid_i), X);
  r.liquid_after = momentaOf(hostCopy(s.grid.momentum_liquid_i), X);
  return r;
}

class ApicOnShape : public ::testing::TestWithParam<ElementType> {};

TEST_P(ApicOnShape, RoundTripKeepsLinearAndAngularMomentumOfBothPhases) {
  // Jiang et al. (2015) Sec. 5.3: with C_p = B_p D_p^-1 the G2P and the P2G each conserve
  // angular momentum; on Tri3 and on rectangular Quad4 cells C_p = sum v_i (grad N_i)^T is
  // that C_p. The scene lies at x ~ 10 m, y ~ -3 m, so an error shows in the angular sums.
  Scene s = makeScene(GetParam(), 3);
  TransferSettings apic{TransferScheme::Apic, {}, s.mesh.coordinates};
  const RoundTrip r = roundTrip(s, apic);
  // round-off: a few ulps of the sums of |m v| |x|
  const Real solid = 1e-14 * r.solid_scale, liquid = 1e-14 * r.liquid_scale;
  for (int d = 0; d < kDim; ++d) {
    EXPECT_NEAR(r.solid_after.linear[d], r.solid_before.linear[d], solid);
    EXPECT_NEAR(r.liquid_after.linear[d], r.liquid_before.linear[d], liquid);
  }
  EXPECT_NEAR(r.solid_after.angular, r.solid_before.angular, solid);
  EXPECT_NEAR(r.liquid_after.angular, r.liquid_before.angular, liquid);

  // The same round trip with PIC (FLIP fully blended) loses angular momentum: the test sees
  // the difference.
  Scene pic_scene = makeScene(GetParam(), 3);
  const RoundTrip pic =
      roundTrip(pic_scene, TransferSettings{TransferScheme::Flip, {1.0, 0.0}, {}});
  EXPECT_GT(std::fabs(pic.solid_after.angular - pic.solid_before.angular), 1e-3 * pic.solid_scale);
}

TEST(Apic, OnTrianglesTheRoundTripGivesTheGridVelocitiesBack) {
  // With linear triangles C_p (x_i - x_p) = sum_j v_j (N_j(x_i) - N_j(x_p)) = v_i - v_p, so
  // every point hands each of its nodes that node's own velocity: the remap reproduces the
  // grid velocities exactly (APIC loses nothing there). Bilinear quads keep the momenta only.
  Scene s = makeScene(ElementType::Tri3, 5);
  TransferSettings apic{TransferScheme::Apic, {}, s.mesh.coordinates};
  NodeRecords records;
  mapPointsToGrid(s.points, s.shapes, liquidFlags(), 0.0, apic, s.active, records, s.grid);
  randomGridVelocities(s.grid, s.mesh.numNodes(), 9);
  Kokkos::deep_copy(s.grid.acceleration_solid_i, 0.0);
  Kokkos::deep_copy(s.grid.acceleration_liquid_i, 0.0);
  const auto vs = hostCopy(s.grid.velocity_solid_i), vl = hostCopy(s.grid.velocity_liquid_i);
  updatePointVelocitiesAndMapMomenta(s.shapes, liquidFlags(), s.active, 0.01, apic, s.points,
                                     records, s.grid);
  computeNodalVelocities(s.active, s.grid);
  const auto vs2 = hostCopy(s.grid.velocity_solid_i), vl2 = hostCopy(s.grid.velocity_liquid_i);
  const auto ml = hostCopy(s.grid.mass_liquid_intrinsic_i);
  for (int i = 0; i < s.mesh.numNodes(); ++i)
    for (int d = 0; d < kDim; ++d) {
      EXPECT_NEAR(vs2(i, d), vs(i, d), 1e-13) << "node " << i;
      if (ml(i) > 0) {
        EXPECT_NEAR(vl2(i, d), vl(i, d), 1e-13) << "node " << i;
      }
    }
}

TEST_P(ApicOnShape, LeavesNoPointVelocityTheGridCannotSee) {
  // Random point velocities over a grid whose velocities are zero: what the grid cannot see
  // (the step's grid velocities are what the momentum solve made of the nodal momenta; here
  // set to rest directly). With zero accelerations FLIP keeps the points' velocities and
  // kinetic energy; APIC gives every point v_p = sum N v~_i = 0 and C_p = 0.
  for (const TransferScheme scheme : {TransferScheme::Flip, TransferScheme::Apic}) {
    Scene s = makeScene(GetParam(), 11);
    std::mt19937 rng(13);
    std::uniform_real_distribution<Real> u(-1, 1);
    auto v = hostCopy(s.points.velocity_solid);
    for (int p = 0; p < s.points.count; ++p)
      for (int d = 0; d < kDim; ++d) v(p, d) = u(rng);
    Kokkos::deep_copy(s.points.velocity_solid, v);
    NodeRecords records;
    TransferSettings transfer{scheme, {}, s.mesh.coordinates};
    mapPointsToGrid(s.points, s.shapes, liquidFlags(), 0.0, transfer, s.active, records, s.grid);
    Kokkos::deep_copy(s.grid.velocity_solid_i, 0.0);  // the grid at rest
    Kokkos::deep_copy(s.grid.velocity_liquid_i, 0.0);
    Kokkos::deep_copy(s.grid.acceleration_solid_i, 0.0);
    Kokkos::deep_copy(s.grid.acceleration_liquid_i, 0.0);
    const KineticTotals k = updatePointVelocitiesAndMapMomenta(
        s.shapes, liquidFlags(), s.active, 0.01, transfer, s.points, records, s.grid);
    if (scheme == TransferScheme::Apic) {
      EXPECT_EQ(k.solid, 0.0);
      const auto C = hostCopy(s.points.affine_velocity_solid);
      for (int p = 0; p < s.points.count; ++p)
        for (int c = 0; c < kAffineComponents; ++c) EXPECT_EQ(C(p, c), 0.0);
    } else {
      EXPECT_GT(k.solid, 0.1);
    }
  }
}

TEST_P(ApicOnShape, AffineVelocityOfALinearFieldIsItsGradient) {
  // Grid velocities of a linear field v = v0 + G x: every point gets v(x_p) and C_p = G,
  // and the remap gives the field back at every node (on Quad4 too: a linear field is in
  // the bilinear space, and C_p (x_i - x_p) = G (x_i - x_p)).
  Scene s = makeScene(GetParam(), 17);
  const Real v0[kDim] = {0.3, -0.7}, G[kDim][kDim] = {{0.2, -1.1}, {0.9, 0.4}};
  TransferSettings apic{TransferScheme::Apic, {}, s.mesh.coordinates};
  NodeRecords records;
  mapPointsToGrid(s.points, s.shapes, liquidFlags(), 0.0, apic, s.active, records, s.grid);
  const auto X = hostCopy(s.mesh.coordinates);
  auto vs = Kokkos::create_mirror_view(s.grid.velocity_solid_i);
  for (int i = 0; i < s.mesh.numNodes(); ++i)
    for (int d = 0; d < kDim; ++d) vs(i, d) = v0[d] + G[d][0] * X(i, 0) + G[d][1] * X(i, 1);
  Kokkos::deep_copy(s.grid.velocity_solid_i, vs);
  Kokkos::deep_copy(s.grid.velocity_liquid_i, vs);
  Kokkos::deep_copy(s.grid.acceleration_solid_i, 0.0);
  Kokkos::deep_copy(s.grid.acceleration_liquid_i, 0.0);
  updatePointVelocitiesAndMapMomenta(s.shapes, liquidFlags(), s.active, 0.01, apic, s.points,
                                     records, s.grid);
  computeNodalVelocities(s.active, s.grid);
  const auto x = hostCopy(s.points.position), v = hostCopy(s.points.velocity_solid);
  const auto C = hostCopy(s.points.affine_velocity_solid);
  const auto CL = hostCopy(s.points.affine_velocity_liquid);
  const auto material = hostCopy(s.points.material);
  for (int p = 0; p < s.points.count; ++p)
    for (int d = 0; d < kDim; ++d) {
      EXPECT_NEAR(v(p, d), v0[d] + G[d][0] * x(p, 0) + G[d][1] * x(p, 1), 1e-12);
      for (int k = 0; k < kDim; ++k) {
        EXPECT_NEAR(C(p, d * kDim + k), G[d][k], 1e-12);
        if (material(p) == 0) {
          EXPECT_NEAR(CL(p, d * kDim + k), G[d][k], 1e-12);
        }
      }
    }
  const auto after = hostCopy(s.grid.velocity_solid_i);
  for (int i = 0; i < s.mesh.numNodes(); ++i)
    for (int d = 0; d < kDim; ++d)
      EXPECT_NEAR(after(i, d), v0[d] + G[d][0] * X(i, 0) + G[d][1] * X(i, 1), 1e-12)
          << "node " << i;
}

TEST_P(ApicOnShape, TpicKeepsLinearMomentumAndTakesTheGridVelocity) {
  // TPIC: v_p = sum N v~_i, the remap without C; the linear momentum of the round trip is
  // kept to round-off (sum N = 1), and a point's velocity is the grid's interpolation.
  Scene s = makeScene(GetParam(), 3);
  const RoundTrip r = roundTrip(s, TransferSettings{TransferScheme::Tpic, {}, s.mesh.coordinates});
  for (int d = 0; d < kDim; ++d) {
    EXPECT_NEAR(r.solid_after.linear[d], r.solid_before.linear[d], 1e-14 * r.solid_scale);
    EXPECT_NEAR(r.liquid_after.linear[d], r.liquid_before.linear[d], 1e-14 * r.liquid_scale);
  }
}

/// Random values in [-1, 1) for a (count x kDim) View.
template <class View>
void randomise(const View& field, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<Real> u(-1, 1);
  auto host = Kokkos::create_mirror_view(field);
  for (int i = 0; i < static_cast<int>(host.extent(0)); ++i)
    for (int d = 0; d < kDim; ++d) host(i, d) = u(rng);
  Kokkos::deep_copy(field, host);
}

/// The point velocities and C_p that `transfer` makes of the same random point velocities,
/// grid velocities v~_i and accelerations a_i, in a step of dt.
struct PointUpdate {
  Kokkos::View<Real*[kDim], Kokkos::HostSpace> solid, liquid;
  Kokkos::View<Real*[kAffineComponents], Kokkos::HostSpace> affine_solid, affine_liquid;
};

PointUpdate updateFromRandomState(Scene& s, const TransferSettings& transfer, Real dt) {
  randomise(s.points.velocity_solid, 21);
  randomise(s.points.velocity_liquid, 22);
  NodeRecords records;
  mapPointsToGrid(s.points, s.shapes, liquidFlags(), 0.0, transfer, s.active, records, s.grid);
  randomise(s.grid.velocity_solid_i, 23);
  randomise(s.grid.velocity_liquid_i, 24);
  randomise(s.grid.acceleration_solid_i, 25);
  randomise(s.grid.acceleration_liquid_i, 26);
  updatePointVelocitiesAndMapMomenta(s.shapes, liquidFlags(), s.active, dt, transfer, s.points,
                                     records, s.grid);
  return {hostCopy(s.points.velocity_solid), hostCopy(s.points.velocity_liquid),
          hostCopy(s.points.affine_velocity_solid), hostCopy(s.points.affine_velocity_liquid)};
}

class AffineFlipOnMesh : public ::testing::TestWithParam<int> {
 protected:
  static Mesh mesh() {
    switch (GetParam()) {
      case 0:
        return test::rectangleMesh(3, 2, 1.5, 1.0, ElementType::Tri3, 10.0, -3.0);
      case 1:
        return test::rectangleMesh(3, 2, 1.5, 1.0, ElementType::Quad4, 10.0, -3.0);
      default:
        return test::gridMesh(4, 3, 2.0, 1.5, ShapeFamily::Gimp, 10.0, -3.0);
    }
  }
};

TEST_P(AffineFlipOnMesh, RatesBlendApicWithFlipByOneMinusExpOfRateTimesStep) {
  // VelocityBlend: per phase v = v_APIC + (1 - alpha)(v_p + dt sum N a_i - v_APIC), alpha =
  // 1 - exp(-rate dt); C_p stays APIC's. Checked against the APIC and FLIP updates of the
  // same state, each with its own kernel; a phase without a rate is APIC's.
  const Real dt = 2e-3;
  const Mesh reference = mesh();
  Scene a = makeScene(reference, 5), f = makeScene(reference, 5);
  const PointUpdate apic =
      updateFromRandomState(a, TransferSettings{TransferScheme::Apic, {}, a.mesh.coordinates}, dt);
  const PointUpdate flip =
      updateFromRandomState(f, TransferSettings{TransferScheme::Flip, {}, f.mesh.coordinates}, dt);
  const auto material = hostCopy(a.points.material);
  struct Case {
    Real solid_rate, liquid_rate;
  };
  for (const Case c : {Case{150, 0}, Case{0, 40}, Case{150, 40}}) {
    // alpha = 1 - exp(-0.3) = 0.2591818 (150/s), 1 - exp(-0.08) = 0.0768837 (40/s); 1: APIC
    const Real alpha_s = c.solid_rate > 0 ? 1 - std::exp(-c.solid_rate * dt) : 1;
    const Real alpha_l = c.liquid_rate > 0 ? 1 - std::exp(-c.liquid_rate * dt) : 1;
    VelocityBlend blend;
    blend.solid_rate = c.solid_rate;
    blend.liquid_rate = c.liquid_rate;
    Scene r = makeScene(reference, 5);
    const PointUpdate both = updateFromRandomState(
        r, TransferSettings{TransferScheme::Apic, blend, r.mesh.coordinates}, dt);
    Real moved_solid = 0, moved_liquid = 0;  // the FLIP share must matter: |v_FLIP - v_APIC|
    for (int p = 0; p < a.points.count; ++p) {
      for (int d = 0; d < kDim; ++d) {
        EXPECT_NEAR(both.solid(p, d), alpha_s * apic.solid(p, d) + (1 - alpha_s) * flip.solid(p, d),
                    1e-13)
            << "point " << p << " rates " << c.solid_rate << " " << c.liquid_rate;
        moved_solid += std::abs(flip.solid(p, d) - apic.solid(p, d));
        if (material(p) == 0) {
          EXPECT_NEAR(both.liquid(p, d),
                      alpha_l * apic.liquid(p, d) + (1 - alpha_l) * flip.liquid(p, d), 1e-13)
              << "point " << p << " rates " << c.solid_rate << " " << c.liquid_rate;
          moved_liquid += std::abs(flip.liquid(p, d) - apic.liquid(p, d));
        }
      }
      for (int k = 0; k < kAffineComponents; ++k) {
        EXPECT_EQ(both.affine_solid(p, k), apic.affine_solid(p, k)) << "point " << p;
        if (material(p) == 0) {
          EXPECT_EQ(both.affine_liquid(p, k), apic.affine_liquid(p, k)) << "point " << p;
        }
      }
    }
    EXPECT_GT(moved_solid, 0.1 * a.points.count);
    EXPECT_GT(moved_liquid, 0.05 * a.points.count);
  }
}

TEST(GridShares, AreOneMinusExpOfRateTimesStepOrThePerStepShares) {
  const VelocityBlend per_step{0.05, 0.2};
  EXPECT_EQ(gridShares(TransferScheme::Flip, per_step, 1e-3).solid, 0.05);
  EXPECT_EQ(gridShares(TransferScheme::Flip, per_step, 1e-3).liquid, 0.2);
  EXPECT_EQ(gridShares(TransferScheme::Apic, per_step, 1e-3).solid, 1.0);  // APIC in full
  EXPECT_EQ(gridShares(TransferScheme::Apic, per_step, 1e-3).liquid, 1.0);
  VelocityBlend rates;
  rates.solid_rate = 100;
  rates.liquid_rate = 10;
  // 1 - exp(-0.1) = 0.1 - 0.1^2/2 + 0.1^3/6 - 0.1^4/24 + ... = 0.09516258196404048;
  // 1 - exp(-0.01) = 0.009950166250831947
  for (const TransferScheme scheme : {TransferScheme::Flip, TransferScheme::Apic}) {
    EXPECT_NEAR(gridShares(scheme, rates, 1e-3).solid, 0.09516258196404048, 1e-16);
    EXPECT_NEAR(gridShares(scheme, rates, 1e-3).liquid, 0.009950166250831947, 1e-17);
  }
  // two half steps damp as one whole: (1 - a(dt/2))^2 = 1 - a(dt)
  const Real half = gridShares(TransferScheme::Apic, rates, 5e-4).solid;
  EXPECT_NEAR((1 - half) * (1 - half), 1 - gridShares(TransferScheme::Apic, rates, 1e-3).solid,
              1e-15);
}

std::string meshName(const ::testing::TestParamInfo<int>& info) {
  return info.param == 0 ? "Tri3" : info.param == 1 ? "Quad4" : "Gimp";
}

INSTANTIATE_TEST_SUITE_P(Meshes, AffineFlipOnMesh, ::testing::Values(0, 1, 2), meshName);

INSTANTIATE_TEST_SUITE_P(Shapes, ApicOnShape,
                         ::testing::Values(ElementType::Tri3, ElementType::Quad4),
                         [](const auto& info) {
                           return info.param == ElementType::Tri3 ? "Tri3" : "Quad4";
                         });

}  // namespace
}  // namespace argine
